// The ground truth for multiple scattering: the random walk on the Smith microsurface of
//   Heitz, Hanika, d'Eon & Jakob, "Multiple-scattering microfacet BSDFs with the Smith model", SIGGRAPH 2016,
// for a GGX conductor. The microsurface is a volume-like medium of facets: a ray travelling in direction w at
// height h meets the surface after a distance set by Smith's Λ(w) and the height distribution (uniform on
// [-1, 1] here; the result does not depend on it), reflects off a facet normal drawn from the distribution of
// normals visible from where it came, and either meets the surface again or leaves. Its first bounce is
// exactly the single-scattering BRDF with height-correlated Smith G2; the later bounces are what that BRDF
// drops. Fresnel: Schlick's of f0 at every bounce, at the angle between the ray and the facet it hits, per
// channel (f0 is a number or an [r, g, b] triple; every channel rides the same paths).
import { seededRandom } from './microsurface.js';
import { fresnelSchlick } from './fresnel.js';
import { clampAlpha, ndfGGXFromSin2 } from './ndf.js';

/** Bounces after which a path is dropped (and counted): with F = 1 all the energy left is in such paths. */
export const WALK_MAX_BOUNCES = 100;

const START_HEIGHT = 2; // above the highest facet (heights lie in [-1, 1])
const heightCdf = (h) => Math.min(Math.max((h + 1) / 2, 0), 1);

const normalize = (x, y, z) => {
  const n = Math.hypot(x, y, z);
  return [x / n, y / n, z / n];
};

/** Smith's Λ for GGX in either hemisphere: (-1 + sign(z) sqrt(1 + alpha² tan²θ)) / 2 (so Λ(-w) = -1 - Λ(w)). */
function lambdaGGX(w, alpha) {
  const root = Math.sqrt(1 + (alpha * alpha * (w[0] * w[0] + w[1] * w[1])) / (w[2] * w[2]));
  return w[2] > 0 ? (root - 1) / 2 : -(root + 1) / 2;
}

/**
 * The height of the next intersection of a ray leaving height h in direction w, or null when it escapes.
 * The chance of meeting the surface below C1(h') is 1 - (C1(h)/C1(h'))^Λ(w) [3, Sec. 4]; inverted,
 * C1(h') = C1(h) / (1 - u)^(1/Λ). Upwards, u > 1 - G1(w, h) = 1 - C1(h)^Λ would put h' above the surface: the
 * ray escapes. Downwards (Λ ≤ -1) it always meets the surface.
 */
function nextHeight(w, h, u, alpha) {
  if (w[2] === 0) return h;
  const lambda = lambdaGGX(w, alpha);
  if (w[2] > 0 && (lambda === 0 || u > 1 - heightCdf(h) ** lambda)) return null;
  const c = heightCdf(h) / (1 - u) ** (1 / lambda);
  return 2 * Math.min(c, 1) - 1;
}

/**
 * A GGX normal drawn from the normals visible from direction wi (wi may point below the horizon, as it does
 * inside the walk), density ∝ max(0, wi·m) D(m): stretched to alpha = 1, where that is the distribution of
 * normalize(c + wi) for c uniform on the unit sphere, restricted to the spherical cap c.z > -wi.z
 * (Dupuy & Benyoub 2023, "Sampling visible GGX normals with spherical caps"), then stretched back.
 */
export function sampleVisibleNormalGGX(wi, alpha, u1, u2) {
  const a = clampAlpha(alpha);
  const [x, y, z] = normalize(a * wi[0], a * wi[1], wi[2]);
  const cz = (1 - u1) * (1 + z) - z;
  const sr = Math.sqrt(Math.max((1 - cz) * (1 + cz), 0));
  const phi = 2 * Math.PI * u2;
  const h = [sr * Math.cos(phi) + x, sr * Math.sin(phi) + y, Math.max(cz + z, 0)];
  // straight from below (wi = -n) no normal is visible and h = 0; the walk never asks (it escapes first)
  return h[0] === 0 && h[1] === 0 && h[2] === 0 ? [0, 0, 1] : normalize(a * h[0], a * h[1], h[2]);
}

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * One walk from direction wi (pointing away from the surface, the light's side). Calls visit(order, h, wr)
 * at every intersection before the ray is reflected (wr: the direction it arrived in), multiplies `weight`
 * (one entry per channel) by the Fresnel of each bounce, and returns the number of bounces when it escapes,
 * or 0 when it is dropped after WALK_MAX_BOUNCES.
 */
function walk(wi, alpha, f0s, weight, rand, visit) {
  let wr = [-wi[0], -wi[1], -wi[2]];
  let h = START_HEIGHT;
  for (let order = 1; order <= WALK_MAX_BOUNCES + 1; order++) {
    h = nextHeight(wr, h, rand(), alpha);
    if (h === null) return order - 1;
    if (order > WALK_MAX_BOUNCES) return 0;
    visit?.(order, h, wr);
    const from = [-wr[0], -wr[1], -wr[2]];
    const m = sampleVisibleNormalGGX(from, alpha, rand(), rand());
    const fm = Math.max(dot(from, m), 0);
    for (let c = 0; c < f0s.length; c++) weight[c] *= fresnelSchlick(f0s[c], fm);
    wr = [2 * fm * m[0] - from[0], 2 * fm * m[1] - from[1], 2 * fm * m[2] - from[2]];
  }
  return 0;
}

/** Mean and standard error (of the mean) per channel from sums of x and x². */
function meanAndError(sum, sum2, n) {
  const mean = sum.map((s) => s / n);
  const error = sum2.map((s2, c) => Math.sqrt(Math.max(s2 / n - mean[c] * mean[c], 0) / Math.max(n - 1, 1)));
  return { mean, error };
}

const shaped = (f0, list) => (Array.isArray(f0) ? list : list[0]);

/**
 * Directional albedo of a GGX conductor by the random walk [3]: `samples` paths from the direction at
 * cos θ = mu, seeded (the same seed gives the same numbers). Returns { albedo, standardError, single,
 * singleStandardError, dropped }: all bounces, the first bounce alone (the single-scattering albedo), each
 * with its Monte Carlo standard error, and the share of paths dropped at WALK_MAX_BOUNCES.
 */
export function randomWalkAlbedoGGX(mu, alpha, f0, samples, seed = 1) {
  const f0s = [].concat(f0);
  const a = clampAlpha(alpha);
  const c = Math.min(Math.max(mu, 1e-6), 1);
  const wi = [Math.sqrt((1 - c) * (1 + c)), 0, c];
  const rand = seededRandom(seed);
  const zeros = () => f0s.map(() => 0);
  const [sum, sum2, one, one2] = [zeros(), zeros(), zeros(), zeros()];
  let dropped = 0;
  for (let i = 0; i < samples; i++) {
    const weight = f0s.map(() => 1);
    const bounces = walk(wi, a, f0s, weight, rand);
    if (bounces === 0) dropped++;
    for (let k = 0; k < f0s.length && bounces > 0; k++) {
      sum[k] += weight[k];
      sum2[k] += weight[k] * weight[k];
      if (bounces === 1) [one[k], one2[k]] = [one[k] + weight[k], one2[k] + weight[k] * weight[k]];
    }
  }
  const all = meanAndError(sum, sum2, samples);
  const first = meanAndError(one, one2, samples);
  return {
    albedo: shaped(f0, all.mean),
    standardError: shaped(f0, all.error),
    single: shaped(f0, first.mean),
    singleStandardError: shaped(f0, first.error),
    dropped: dropped / samples,
  };
}

/**
 * The walk's phase function for a conductor with F = 1 [3, eq. 19 with the visible-normal density]:
 * D_wi(h) / (4 wi·h) = D(h) / (4 (1 + Λ(wi)) wi.z), h = normalize(wi + wo); 0 when h is below the horizon.
 */
function phaseGGX(wi, wo, alpha) {
  const [hx, hy, hz] = normalize(wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]);
  if (!(hz > 0)) return 0;
  const area = (1 + lambdaGGX(wi, alpha)) * wi[2];
  return area > 0 ? ndfGGXFromSin2(hz, hx * hx + hy * hy, alpha) / (4 * area) : 0;
}

/**
 * The BRDF f(l, v) in 1/sr by the same walk, with next-event estimation towards v at every bounce [3, Sec. 5]:
 * the phase function times the chance G1(v, h) = C1(h)^Λ(v) that v leaves from that height, with the Fresnel
 * of the facet that would send the light to v. Returns { value, standardError, single, singleStandardError }
 * (single: the first bounce, which is the single-scattering BRDF D G2 F / (4 nl nv) in expectation).
 */
export function randomWalkBRDFGGX(l, v, alpha, f0, samples, seed = 1) {
  const f0s = [].concat(f0);
  const zeros = () => f0s.map(() => 0);
  const [sum, sum2, one, one2] = [zeros(), zeros(), zeros(), zeros()];
  if (!(l[2] > 0 && v[2] > 0)) {
    const none = shaped(f0, zeros());
    return { value: none, standardError: none, single: none, singleStandardError: none };
  }
  const a = clampAlpha(alpha);
  const rand = seededRandom(seed);
  const lambdaV = lambdaGGX(v, a);
  for (let i = 0; i < samples; i++) {
    const weight = f0s.map(() => 1);
    const [path, first] = [zeros(), zeros()];
    walk(l, a, f0s, weight, rand, (order, h, wr) => {
      const from = [-wr[0], -wr[1], -wr[2]];
      const p = phaseGGX(from, v, a) * heightCdf(h) ** lambdaV;
      const hv = normalize(from[0] + v[0], from[1] + v[1], from[2] + v[2]);
      f0s.forEach((f, c) => {
        const x = (weight[c] * p * fresnelSchlick(f, Math.max(dot(from, hv), 0))) / v[2];
        path[c] += x;
        if (order === 1) first[c] = x;
      });
    });
    f0s.forEach((_, c) => {
      [sum[c], sum2[c]] = [sum[c] + path[c], sum2[c] + path[c] * path[c]];
      [one[c], one2[c]] = [one[c] + first[c], one2[c] + first[c] * first[c]];
    });
  }
  const all = meanAndError(sum, sum2, samples);
  const single = meanAndError(one, one2, samples);
  return {
    value: shaped(f0, all.mean),
    standardError: shaped(f0, all.error),
    single: shaped(f0, single.mean),
    singleStandardError: shaped(f0, single.error),
  };
}
