// The table the GPU reads the energy lost, 1 - E(mu, alpha) and 1 - E_avg(alpha), from (GGX, height-correlated
// Smith, F = 1), built from the float64 functions and looked up by the same bilinear rule in JS and in GLSL
// (albedoLossTableGGX in shaders/multiple-scattering.glsl), so the two can be compared node for node. The losses,
// not E, are stored: near alpha = 0 they are ~1e-7 and float32 keeps their digits, where 1 - E would have none.
import { averageAlbedo, dfgSplitSum } from './integrate.js';
import {
  energyCompensationTurquin,
  fresnelAverage,
  fresnelMultipleScatteringKullaConty,
} from './multiple-scattering.js';

/**
 * Nodes per axis. Axes: x = cbrt(mu), y = cbrt(alpha): E changes fastest where mu and alpha are both small
 * (the grazing dip scales with alpha), and cube roots crowd the nodes there (half the error square roots
 * gave). Bilinear error against the exact E, on log-spaced points (see the tests): below 1.3e-3 for mu,
 * alpha >= 0.01, 8.5e-4 for >= 0.02, 5e-4 for >= 0.05; larger where both are below 0.01 (a near-mirror's
 * grazing dip is narrower than a cell there). 128² nodes would give ~3e-4 for >= 0.01 but take 4× the build.
 */
export const ALBEDO_TABLE_SIZE = 64;

/**
 * { size, data }: RGBA float32 texels, row j = alpha (j/(size - 1))³, column i = mu (i/(size - 1))³;
 * R = 1 - E(mu, alpha), G = 1 - E_avg(alpha), B = the split sum's bias (the Fresnel part, so that the albedo
 * with Schlick's F is f0 E + (1 - f0) bias). `dfg(mu, alpha)` gives [scale, bias] with E = scale + bias
 * (tableSplitSum unless a test passes its own); E_avg is the cosine-weighted average of E.
 */
/** The split sum the table is built from: 12 Gauss–Legendre nodes per piece (~0.2 ms a texel, ~1 s a table). */
export const tableSplitSum = (mu, alpha) => dfgSplitSum(mu, alpha, {}, { nodes: 12 });

export function buildAlbedoTableGGX(size = ALBEDO_TABLE_SIZE, dfg = tableSplitSum) {
  const data = new Float32Array(size * size * 4);
  for (let j = 0; j < size; j++) {
    const alpha = (j / (size - 1)) ** 3;
    const row = Array.from({ length: size }, (_, i) => dfg((i / (size - 1)) ** 3, alpha));
    const avg = averageAlbedo((mu) => {
      const [scale, bias] = dfg(mu, alpha);
      return scale + bias;
    });
    // E may round to 1 + 1e-16: the losses are kept at 0 or above
    row.forEach(([scale, bias], i) => {
      data.set([Math.max(1 - scale - bias, 0), Math.max(1 - avg, 0), bias, 1], 4 * (j * size + i));
    });
  }
  return { size, data };
}

/** [1 - E(mu, alpha), 1 - E_avg(alpha), bias] from the table, bilinear in (cbrt(mu), cbrt(alpha)), clamped. */
export function albedoLossTableGGX(table, mu, alpha) {
  const { size, data } = table;
  const x = Math.cbrt(Math.min(Math.max(mu, 0), 1)) * (size - 1);
  const y = Math.cbrt(Math.min(Math.max(alpha, 0), 1)) * (size - 1);
  const [i, j] = [Math.min(Math.floor(x), size - 2), Math.min(Math.floor(y), size - 2)];
  const [fx, fy] = [x - i, y - j];
  const at = (ii, jj, c) => data[4 * (jj * size + ii) + c];
  return [0, 1, 2].map((c) => {
    const lo = at(i, j, c) + (at(i + 1, j, c) - at(i, j, c)) * fx;
    const hi = at(i, j + 1, c) + (at(i + 1, j + 1, c) - at(i, j + 1, c)) * fx;
    return lo + (hi - lo) * fy;
  });
}

/**
 * Directional albedo ∫ f (n·l) dω of GGX with Schlick's F at f0 (one channel), from the table, with a
 * compensation ('none', 'kullaConty' or 'turquin', see multiple-scattering.js): what a shader computes.
 */
export function specularAlbedoFromTable(table, mu, alpha, f0, compensation) {
  const [loss, lossAvg, bias] = albedoLossTableGGX(table, mu, alpha);
  const E = 1 - loss;
  const single = f0 * E + (1 - f0) * bias;
  const factor = fresnelMultipleScatteringKullaConty(fresnelAverage(f0), 1 - lossAvg);
  if (compensation === 'kullaConty') return single + factor * loss;
  if (compensation === 'turquin') return single * energyCompensationTurquin(f0, E);
  return single;
}
