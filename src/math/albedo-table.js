// The table the GPU reads the energy lost, 1 - E(mu, alpha) and 1 - E_avg(alpha), from (GGX, height-correlated
// Smith, F = 1), built from the float64 functions and looked up by the same bilinear rule in JS and in GLSL
// (albedoLossTableGGX in shaders/multiple-scattering.glsl), so the two can be compared node for node. The losses,
// not E, are stored: near alpha = 0 they are ~1e-7 and float32 keeps their digits, where 1 - E would have none.
import { albedoGGX } from './integrate.js';
import { cosineWeightedAverage } from './multiple-scattering.js';

/**
 * Nodes per axis. Axes: x = sqrt(mu), y = sqrt(alpha): E changes fastest where mu and alpha are both small
 * (the grazing dip scales with alpha), and square roots spread those nodes out. Bilinear error against the
 * exact E: below 5e-4 for mu, alpha >= 0.01 (see the tests); up to 0.03 where both are below 0.01 (a
 * near-mirror's grazing dip is narrower than a cell there).
 */
export const ALBEDO_TABLE_SIZE = 64;

/**
 * { size, data }: RGBA float32 texels, row j = alpha (j/(size - 1))², column i = mu (i/(size - 1))²;
 * R = 1 - E(mu, alpha), G = 1 - E_avg(alpha). `albedo(mu, alpha)` is the E to tabulate (albedoGGX unless a test
 * passes its own); E_avg is its cosine-weighted average.
 */
export function buildAlbedoTableGGX(size = ALBEDO_TABLE_SIZE, albedo = albedoGGX) {
  const data = new Float32Array(size * size * 4);
  for (let j = 0; j < size; j++) {
    const alpha = (j / (size - 1)) ** 2;
    const avg = cosineWeightedAverage((mu) => albedo(mu, alpha));
    for (let i = 0; i < size; i++) {
      const k = 4 * (j * size + i);
      data.set([Math.max(1 - albedo((i / (size - 1)) ** 2, alpha), 0), Math.max(1 - avg, 0), 0, 1], k); // E may round to 1 + 1e-16
    }
  }
  return { size, data };
}

/** [1 - E(mu, alpha), 1 - E_avg(alpha)] from the table, bilinear in (sqrt(mu), sqrt(alpha)), clamped to the table's range. */
export function albedoLossTableGGX(table, mu, alpha) {
  const { size, data } = table;
  const x = Math.sqrt(Math.min(Math.max(mu, 0), 1)) * (size - 1);
  const y = Math.sqrt(Math.min(Math.max(alpha, 0), 1)) * (size - 1);
  const [i, j] = [Math.min(Math.floor(x), size - 2), Math.min(Math.floor(y), size - 2)];
  const [fx, fy] = [x - i, y - j];
  const at = (ii, jj, c) => data[4 * (jj * size + ii) + c];
  return [0, 1].map((c) => {
    const lo = at(i, j, c) + (at(i + 1, j, c) - at(i, j, c)) * fx;
    const hi = at(i, j + 1, c) + (at(i + 1, j + 1, c) - at(i, j + 1, c)) * fx;
    return lo + (hi - lo) * fy;
  });
}
