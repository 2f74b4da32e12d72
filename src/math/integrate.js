// The reflectance equation, integrated two ways: by quadrature over the hemisphere, and by importance
// sampling the GGX distribution of normals. Directional albedo E(mu) = ∫ f(l, v)(n·l) dω_l is the share of
// light from direction v that the BRDF sends back out; with F = 1 it measures what the microfacet model
// loses by ignoring light that bounces more than once (the white furnace).
import { ndfGGX, clampAlpha } from './ndf.js';
import { visibilitySmithGGXCorrelated } from './visibility.js';

/** Direction of polar angle cos = mu in the x-z plane (the view of an isotropic BRDF loses nothing). */
export function directionFromCos(mu) {
  const c = Math.min(Math.max(mu, -1), 1);
  return [Math.sqrt((1 - c) * (1 + c)), 0, c];
}

/** Hammersley point i of n (0 <= i < n): a deterministic, evenly spread pair in [0, 1)². */
export function hammersley(i, n) {
  let bits = i;
  bits = ((bits << 16) | (bits >>> 16)) >>> 0;
  bits = (((bits & 0x55555555) << 1) | ((bits & 0xaaaaaaaa) >>> 1)) >>> 0;
  bits = (((bits & 0x33333333) << 2) | ((bits & 0xcccccccc) >>> 2)) >>> 0;
  bits = (((bits & 0x0f0f0f0f) << 4) | ((bits & 0xf0f0f0f0) >>> 4)) >>> 0;
  bits = (((bits & 0x00ff00ff) << 8) | ((bits & 0xff00ff00) >>> 8)) >>> 0;
  return [(i + 0.5) / n, bits / 2 ** 32];
}

/** A GGX microfacet normal for (u1, u2): pdf D(m)(n·m). tan²theta = alpha² u1/(1 - u1). */
export function sampleGGXNormal(u1, u2, alpha) {
  const a = clampAlpha(alpha);
  const t2 = (a * a * u1) / (1 - u1);
  const c = 1 / Math.sqrt(1 + t2);
  const s = Math.sqrt(t2) * c;
  const phi = 2 * Math.PI * u2;
  return [s * Math.cos(phi), s * Math.sin(phi), c];
}

/** Mirror of v about m. */
export function reflect(v, m) {
  const d = 2 * (v[0] * m[0] + v[1] * m[1] + v[2] * m[2]);
  return [d * m[0] - v[0], d * m[1] - v[1], d * m[2] - v[2]];
}

/**
 * ∫ g(l)(n·l) dω over the hemisphere by the midpoint rule in (mu = n·l, phi): n × 2n cells.
 * Exact for smooth g as n grows; slow to converge for sharp lobes (see the importance-sampled form).
 */
export function hemisphereIntegral(g, n = 256) {
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const mu = (i + 0.5) / n;
    const s = Math.sqrt((1 - mu) * (1 + mu));
    for (let j = 0; j < 2 * n; j++) {
      const phi = (Math.PI * (j + 0.5)) / n;
      sum += g([s * Math.cos(phi), s * Math.sin(phi), mu]) * mu;
    }
  }
  return (sum * 2 * Math.PI) / (n * 2 * n);
}

/**
 * ∫ f(l, v)(n·l) dω_l with l = reflect(v, m), m drawn from the GGX D(m)(n·m): pdf(l) = D(m)(n·m)/(4 (v·m)).
 * f(l, v) is any BRDF; `alpha` only shapes the sampling.
 */
export function reflectanceImportanceGGX(f, v, alpha, n = 1024) {
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const m = sampleGGXNormal(...hammersley(i, n), alpha);
    const vm = v[0] * m[0] + v[1] * m[1] + v[2] * m[2];
    if (vm <= 0) continue;
    const l = reflect(v, m);
    if (l[2] <= 0) continue;
    const pdf = (ndfGGX(m[2], alpha) * m[2]) / (4 * vm);
    sum += (f(l, v) * l[2]) / pdf;
  }
  return sum / n;
}

/**
 * Directional albedo with GGX, height-correlated Smith and F = 1: the split sum's scale + bias (with F = 1 the
 * Fresnel split adds back up). With the GGX pdf the D cancels: f nl / pdf = V nl (v·m) / (n·m).
 */
export function albedoGGX(mu, alpha, n = 1024) {
  const [scale, bias] = dfgSplitSum(mu, alpha, n);
  return scale + bias;
}

/**
 * ∫ D(m)(n·m) dω for an isotropic D(cos): 2π ∫_0^{π/2} D(cos θ) cos θ sin θ dθ by Simpson's rule in s with
 * θ = (π/2) s², which crowds the nodes near θ = 0 where narrow lobes are. Should be 1 for every NDF.
 */
export function ndfProjectedIntegral(D, n = 4000) {
  const h = 1 / n;
  let sum = 0;
  for (let i = 0; i <= n; i++) {
    const s = i * h;
    const theta = (Math.PI / 2) * s * s;
    const g = D(Math.cos(theta)) * Math.cos(theta) * Math.sin(theta) * Math.PI * s; // dθ/ds = π s
    sum += (i === 0 || i === n ? 1 : i % 2 ? 4 : 2) * g;
  }
  return ((2 * Math.PI * sum * h) / 3);
}

/** Cosine-weighted average of E over incoming directions, E_avg = 2 ∫_0^1 E(mu) mu dmu (midpoint rule). */
export function averageAlbedo(E, n = 64) {
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const mu = (i + 0.5) / n;
    sum += E(mu) * mu;
  }
  return (2 * sum) / n;
}

/**
 * The split-sum DFG term (Karis 2013) for GGX, height-correlated Smith and Schlick's F:
 * ∫ f(l, v)(n·l) dω = F0·scale + bias, since F = F0 (1 - Fc) + Fc with Fc = (1 - v·h)^5.
 * The same estimator as albedoGGX, split by (1 - Fc) and Fc. scale + bias = albedoGGX(mu, alpha) (both capped at 1).
 */
export function dfgSplitSum(mu, alpha, n = 1024) {
  const v = directionFromCos(Math.min(Math.max(mu, 1e-6), 1));
  let scale = 0;
  let bias = 0;
  for (let i = 0; i < n; i++) {
    const m = sampleGGXNormal(...hammersley(i, n), alpha);
    const vm = v[0] * m[0] + v[2] * m[2];
    if (vm <= 0) continue;
    const l = reflect(v, m);
    if (l[2] <= 0) continue;
    const w = (visibilitySmithGGXCorrelated(l[2], v[2], alpha) * l[2] * vm) / m[2];
    const fc = (1 - vm) ** 5;
    scale += (1 - fc) * w;
    bias += fc * w;
  }
  const total = Math.max((scale + bias) / n, 1); // few samples at grazing can overshoot: keep the sum an albedo
  return [scale / n / total, bias / n / total];
}

/** A cosine-distributed direction for (u1, u2): pdf (n·l)/π, so a Lambert estimate is cdiff·L per sample. */
export function sampleCosine(u1, u2) {
  const r = Math.sqrt(u1);
  const phi = 2 * Math.PI * u2;
  return [r * Math.cos(phi), r * Math.sin(phi), Math.sqrt(Math.max(1 - u1, 0))];
}

/** A direction spread uniformly over the cone of half-angle acos(cosMax) around z: pdf 1/(2π(1 - cosMax)). */
export function sampleCone(u1, u2, cosMax) {
  const c = 1 - u1 * (1 - cosMax);
  const s = Math.sqrt(Math.max((1 - c) * (1 + c), 0));
  const phi = 2 * Math.PI * u2;
  return [s * Math.cos(phi), s * Math.sin(phi), c];
}
