// A 3-D microsurface: a periodic Gaussian random heightfield whose slopes have a different spread along x (= t)
// and y (= b), triangulated on a unit grid, and exact ray casting against it. Its heights are a sum of waves with
// random phases (spectral synthesis) drawn from a Gaussian spectrum, so heights and slopes are Gaussian and the
// slopes' distribution is anisotropic Beckmann's: slope along x with standard deviation αx/√2, along y αy/√2.
// Smith's G1 is a prediction about such surfaces; this measures it, per azimuth. Periodic, so rays that leave one
// side come in at the other and no facet is near an edge.
import { seededRandom } from './microsurface.js';

const TAU = 2 * Math.PI;

/** A standard normal draw (Box-Muller) from `rand`. */
const gaussian = (rand) => Math.sqrt(-2 * Math.log(Math.max(rand(), 1e-300))) * Math.cos(TAU * rand());

/**
 * Heights of an n × n periodic grid (row-major, h[j n + i] at x = i, y = j) of a Gaussian surface with correlation
 * C(d) = σ² exp(-dx²/ℓx² - dy²/ℓy²), whose slopes have variance 2σ²/ℓx² = αx²/2 along x (αy²/2 along y): ℓ = 2σ/α.
 * σ is chosen so that the shorter correlation length is `minLength` cells (the facets resolve every bump).
 * `waves` waves, their wave vectors drawn from the spectrum (normal, standard deviation √2/ℓ per axis) and
 * rounded to the grid's periodic lattice 2π m / n. Returns { n, h, sigma, lengths: [ℓx, ℓy] }.
 */
export function generateHeightfield(n, alphaX, alphaY, { seed = 1, waves = 400, minLength = 5 } = {}) {
  const rand = seededRandom(seed);
  const sigma = (minLength * Math.max(alphaX, alphaY)) / 2;
  const [lx, ly] = [(2 * sigma) / alphaX, (2 * sigma) / alphaY];
  const h = new Float64Array(n * n);
  const amp = sigma * Math.sqrt(2 / waves);
  const [cx, sx, cy, sy] = [0, 0, 0, 0].map(() => new Float64Array(n));
  for (let w = 0; w < waves; w++) {
    const kx = (TAU / n) * Math.round(((gaussian(rand) * Math.SQRT2) / lx) * (n / TAU));
    const ky = (TAU / n) * Math.round(((gaussian(rand) * Math.SQRT2) / ly) * (n / TAU));
    const phase = TAU * rand();
    // cos(kx i + ky j + φ) = cos(kx i + φ) cos(ky j) - sin(kx i + φ) sin(ky j): 2n cosines, not n²
    for (let i = 0; i < n; i++) [cx[i], sx[i]] = [Math.cos(kx * i + phase), Math.sin(kx * i + phase)];
    for (let j = 0; j < n; j++) [cy[j], sy[j]] = [Math.cos(ky * j), Math.sin(ky * j)];
    for (let j = 0; j < n; j++) {
      const [c, s, row] = [amp * cy[j], amp * sy[j], j * n];
      for (let i = 0; i < n; i++) h[row + i] += cx[i] * c - sx[i] * s;
    }
  }
  return { n, h, sigma, lengths: [lx, ly] };
}

/** Height at grid point (i, j), wrapped. */
const at = ({ n, h }, i, j) => h[(((j % n) + n) % n) * n + (((i % n) + n) % n)];

/**
 * The two triangles of cell (i, j): k = 0 the lower one (i, j), (i+1, j), (i, j+1); k = 1 the upper one (i+1, j+1),
 * (i, j+1), (i+1, j). Each is a plane z = z0 + sx (x - x0) + sy (y - y0) through its first vertex (x0, y0):
 * returns [x0, y0, z0, sx, sy], its slopes sx along x and sy along y.
 */
export function triangle(field, i, j, k) {
  const [z00, z10, z01, z11] = [at(field, i, j), at(field, i + 1, j), at(field, i, j + 1), at(field, i + 1, j + 1)];
  return k === 0 ? [i, j, z00, z10 - z00, z01 - z00] : [i + 1, j + 1, z11, z11 - z01, z11 - z10];
}

/** The roughness pair the surface's own facets have, αx = √2 · rms slope along x (Beckmann's relation), per area. */
export function facetAlphas(field) {
  const { n } = field;
  let [sxx, syy, area] = [0, 0, 0];
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      for (let k = 0; k < 2; k++) {
        const [, , , sx, sy] = triangle(field, i, j, k);
        // a facet's share of the slope distribution is its footprint, the same for every triangle
        [sxx, syy, area] = [sxx + sx * sx, syy + sy * sy, area + 1];
      }
    }
  }
  return [Math.sqrt((2 * sxx) / area), Math.sqrt((2 * syy) / area)];
}

/** Largest height of each cell's four corners, and of the whole surface (for early exits). */
export function cellMaxima(field) {
  const { n } = field;
  const max = new Float64Array(n * n);
  let top = -Infinity;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const m = Math.max(at(field, i, j), at(field, i + 1, j), at(field, i, j + 1), at(field, i + 1, j + 1));
      max[j * n + i] = m;
      top = Math.max(top, m);
    }
  }
  return { max, top };
}

/** Does the ray p + s d (s in [s0, s1]) meet triangle k of cell (i, j) (its plane, inside its footprint)? */
function hitsTriangle(field, i, j, k, p, d, s0, s1) {
  const [x0, y0, z0, sx, sy] = triangle(field, i, j, k);
  // height of the ray above the plane, linear in s: g(s) = g0 + s g1
  const g0 = p[2] - z0 - sx * (p[0] - x0) - sy * (p[1] - y0);
  const g1 = d[2] - sx * d[0] - sy * d[1];
  if (g1 === 0) return false;
  const s = -g0 / g1;
  if (!(s > s0 && s <= s1)) return false;
  // inside the footprint: lower triangle u, v >= 0, u + v <= 1 with (u, v) from (x0, y0); the upper one mirrored
  const [u, v] = [Math.abs(p[0] + s * d[0] - x0), Math.abs(p[1] + s * d[1] - y0)];
  return u + v <= 1;
}

/**
 * Is the ray from point p (on the surface) along the unit direction d (d.z > 0) blocked by the surface? Walks the
 * grid's cells along the ray's footprint (a 2-D DDA, wrapped), testing both triangles of each cell the ray is not
 * clearly above, until the ray is higher than the highest point.
 */
export function blocked(field, maxima, p, d) {
  const { n } = field;
  const horiz = Math.hypot(d[0], d[1]);
  if (horiz === 0) return false;
  const sEnd = (maxima.top - p[2]) / d[2]; // past this the ray is above everything
  let [i, j] = [Math.floor(p[0]), Math.floor(p[1])];
  const [stepI, stepJ] = [d[0] > 0 ? 1 : -1, d[1] > 0 ? 1 : -1];
  const tDelta = [Math.abs(1 / d[0]), Math.abs(1 / d[1])];
  let tNext = [
    d[0] === 0 ? Infinity : ((d[0] > 0 ? i + 1 : i) - p[0]) / d[0],
    d[1] === 0 ? Infinity : ((d[1] > 0 ? j + 1 : j) - p[1]) / d[1],
  ];
  let s0 = 1e-9;
  while (s0 < sEnd) {
    const s1 = Math.min(tNext[0], tNext[1]);
    const cell = (((j % n) + n) % n) * n + (((i % n) + n) % n);
    // the ray rises, so its lowest point in the cell is where it enters
    if (p[2] + s0 * d[2] <= maxima.max[cell]) {
      if (hitsTriangle(field, i, j, 0, p, d, s0, s1) || hitsTriangle(field, i, j, 1, p, d, s0, s1)) return true;
    }
    s0 = s1;
    if (tNext[0] < tNext[1]) [i, tNext] = [i + stepI, [tNext[0] + tDelta[0], tNext[1]]];
    else [j, tNext] = [j + stepJ, [tNext[0], tNext[1] + tDelta[1]]];
  }
  return false;
}

/** A point of triangle k of cell (i, j) at barycentric-like (a, b), a + b <= 1, lifted by `eps` along z. */
function pointOn(tri, k, a, b, eps) {
  const [x0, y0, z0, sx, sy] = tri;
  const [dx, dy] = k === 0 ? [a, b] : [-a, -b];
  return [x0 + dx, y0 + dy, z0 + sx * dx + sy * dy + eps];
}

/**
 * Measured G1 for the unit direction w (w.z > 0): the projected area of front-facing facets that w sees unblocked,
 * over all of it. `samples` facets are drawn at random (seeded), one ray from a random point of each; a facet's
 * projected area is its footprint times w·(-sx, -sy, 1) (the same footprint for every triangle). Also returns the
 * same share for the facets tilted towards w's azimuth and those tilted away (Smith says both are G1).
 */
export function measuredG1Aniso(field, maxima, w, { samples = 20000, seed = 7 } = {}) {
  const rand = seededRandom(seed);
  const { n } = field;
  const sums = { all: [0, 0], towards: [0, 0], away: [0, 0] };
  for (let r = 0; r < samples; r++) {
    const [i, j, k] = [Math.floor(rand() * n), Math.floor(rand() * n), rand() < 0.5 ? 0 : 1];
    const tri = triangle(field, i, j, k);
    const proj = w[2] - tri[3] * w[0] - tri[4] * w[1];
    if (proj <= 0) continue;
    let [a, b] = [rand(), rand()];
    if (a + b > 1) [a, b] = [1 - a, 1 - b];
    const seen = blocked(field, maxima, pointOn(tri, k, a, b, 1e-9), w) ? 0 : proj;
    const group = -(tri[3] * w[0] + tri[4] * w[1]) > 0 ? sums.towards : sums.away;
    for (const s of [sums.all, group]) [s[0], s[1]] = [s[0] + seen, s[1] + proj];
  }
  const share = ([seen, total]) => (total > 0 ? seen / total : 1);
  return { g1: share(sums.all), towards: share(sums.towards), away: share(sums.away) };
}

/** The surface over (x, y): its height z and the slopes (sx, sy) of the triangle there. */
export function surfaceAt(field, x, y) {
  const [i, j] = [Math.floor(x), Math.floor(y)];
  const k = x - i + (y - j) <= 1 ? 0 : 1;
  const [x0, y0, z0, sx, sy] = triangle(field, i, j, k);
  return { z: z0 + sx * (x - x0) + sy * (y - y0), sx, sy };
}
