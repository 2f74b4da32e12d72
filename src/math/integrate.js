// The reflectance equation, integrated: by quadrature over the hemisphere, by importance sampling the normals
// (GGX or Beckmann), and, for the split sum and the directional albedo, by a deterministic quadrature over the
// microfacet normals accurate to ~1e-7. Directional albedo E(mu) = ∫ f(l, v)(n·l) dω_l is the share of light
// from direction v that the BRDF sends back out; with F = 1 it measures what the microfacet model loses by
// ignoring light that bounces more than once (the white furnace).
import { ALPHA_MIN, ndfGGX, clampAlpha } from './ndf.js';
import { VISIBILITY_TERMS } from './brdf.js';
import { gaussLegendreVector, integrateVector } from './quadrature.js';

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

/** A GGX microfacet normal for (u1, u2), u1 in [0, 1): pdf D(m)(n·m). tan²theta = alpha² u1/(1 - u1). */
export function sampleGGXNormal(u1, u2, alpha) {
  const a = clampAlpha(alpha);
  const t2 = (a * a * u1) / (1 - u1);
  const c = 1 / Math.sqrt(1 + t2);
  const s = Math.sqrt(t2) * c;
  const phi = 2 * Math.PI * u2;
  return [s * Math.cos(phi), s * Math.sin(phi), c];
}

/** A Beckmann microfacet normal for (u1, u2), u1 in [0, 1): pdf D(m)(n·m). tan²theta = -alpha² ln(1 - u1). */
export function sampleBeckmannNormal(u1, u2, alpha) {
  const a = clampAlpha(alpha);
  const t2 = -a * a * Math.log1p(-u1);
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
  return (2 * Math.PI * sum * h) / 3;
}

/**
 * Cosine-weighted average of E over incoming directions, E_avg = 2 ∫_0^1 E(mu) mu dmu, by n-point Gauss-Legendre
 * in s = sqrt(mu) (E_avg = 4 ∫_0^1 E(s²) s³ ds), which crowds the nodes toward grazing where E turns fastest.
 */
export function averageAlbedo(E, n = 16) {
  return gaussLegendreVector((s) => [4 * E(s * s) * s * s * s], 0, 1, n, 1)[0];
}

/** The split sum's terms and their defaults: GGX with height-correlated Smith. */
export const DFG_DEFAULT_TERMS = Object.freeze({ ndf: 'ggx', visibility: 'smithGGXCorrelated' });

// Per NDF, tan²θm at r = sqrt(1 - u), where u is the share of D(m)(n·m) with a polar angle below θm, and r at
// tan²θm. In (u, φ) the measure D(m)(n·m) dω_m is du dφ/2π, so no peak is left however small alpha is; r also
// absorbs the tail u -> 1, where the integrand grows like tan θm ~ (1 - u)^-1/2 at grazing view (GGX).
const NDF_TAN2 = {
  ggx: (r, a2) => (a2 * (1 - r) * (1 + r)) / (r * r),
  beckmann: (r, a2) => -2 * a2 * Math.log(r),
};
const NDF_R = {
  ggx: (t2, a2) => Math.sqrt(a2 / (a2 + t2)),
  beckmann: (t2, a2) => Math.exp(-t2 / (2 * a2)),
};
// Where a visibility term has kinks, as values of v·m given n·v and n·m (the φ integrand depends on φ through
// v·m alone, with n·l = 2 (v·m)(n·m) - n·v): Cook-Torrance's min() of vm/(nv nm), 2 and 2 nl/nv switches there.
const VISIBILITY_KINKS = {
  cookTorrance: [
    (nv, cm) => 2 * nv * cm,
    (nv, cm) => nv / cm,
    (nv, cm) => (4 * cm * cm > 1 ? (2 * nv * cm) / (4 * cm * cm - 1) : Infinity),
  ],
};
const MU_MIN = 1e-6;
const PHI_TOL = 1e-7; // absolute, per φ integral times its weight 2r
const R_TOL = 1e-7; // absolute, for the r integral (E is 1/π of it)
const KINK_SCAN = 96; // steps in θm when looking for where a kink enters the φ range

/** ∫_lo^hi g with x = lo + (hi - lo) s²(3 - 2s): a kink (x - lo)^3/2 at either end becomes smooth in s. */
function smoothedIntegral(integrate, g, lo, hi, tol) {
  if (!(hi > lo)) return [0, 0];
  return integrate(
    (s) => {
      const w = 6 * s * (1 - s) * (hi - lo);
      return g(lo + (hi - lo) * s * s * (3 - 2 * s)).map((y) => y * w);
    },
    0,
    1,
    tol,
    2,
  );
}

/** Roots of h in (0, b) by a scan of `steps` and bisection. */
function roots(h, b, steps) {
  const found = [];
  for (let i = 0, x0 = 0, h0 = h(0); i < steps; i++) {
    const x1 = (b * (i + 1)) / steps;
    const h1 = h(x1);
    if (h0 * h1 < 0) {
      let [lo, hi] = [x0, x1];
      for (let k = 0; k < 60; k++) [lo, hi] = h(lo) * h((lo + hi) / 2) <= 0 ? [lo, (lo + hi) / 2] : [(lo + hi) / 2, hi];
      found.push((lo + hi) / 2);
    }
    [x0, h0] = [x1, h1];
  }
  return found;
}

/**
 * The polar angles θm below θ2 where a kink of V enters the φ range: where it meets v·m at φ = 0, cos(θm - θv),
 * at φ = π, cos(θm + θv), or at φmax, where n·l = 0: v·m = n·v/(2 n·m). The r integral is cut there too.
 */
function kinkAngles(kinks, nv, sv, theta2) {
  const tv = Math.atan2(sv, nv);
  const ends = [(t) => Math.cos(t - tv), (t) => Math.cos(t + tv), (t) => nv / (2 * Math.cos(t))];
  return kinks.flatMap((k) => ends.flatMap((end) => roots((t) => k(nv, Math.cos(t)) - end(t), theta2, KINK_SCAN)));
}

/**
 * ∫_0^φmax of the split sum's integrand [(1 - Fc) w, Fc w], w = V (n·l)(v·m)/(n·m), for the normals at polar
 * angle θm (cos cm, sin sm): in pieces between the kinks of V, each with its nodes crowded toward its end by
 * φ = hi - Δ(1 - s)³, for at φmax n·l -> 0 and V (n·l) turns over in a layer as thin as the lesser of n·v
 * and alpha.
 */
function phiIntegral({ nv, sv, vis, kinks, params, integrate, fresnel }, cm, sm, phiMax, tol) {
  const angles = { nl: 0, nv, nh: cm, lh: 0 };
  const y = [0, 0]; // reused: the integrators read it before the next call
  const integrand = (phi, weight) => {
    const vm = sv * sm * Math.cos(phi) + nv * cm;
    const nl = 2 * vm * cm - nv;
    angles.nl = nl;
    angles.lh = vm;
    const w = (vis(angles, params) * nl * vm * weight) / cm;
    const fc = fresnel ? 0 : (1 - vm) ** 5;
    y[0] = (fresnel ? fresnel(vm) : 1 - fc) * w;
    y[1] = fc * w;
    return y;
  };
  const cuts = [0];
  for (const k of kinks) {
    const phi = Math.acos(Math.min(Math.max((k(nv, cm) - nv * cm) / (sv * sm), -1), 1));
    if (phi > 0 && phi < phiMax) cuts.push(phi);
  }
  cuts.sort((x, z) => x - z).push(phiMax);
  let scale = 0;
  let bias = 0;
  for (let k = 0; k + 1 < cuts.length; k++) {
    const [lo, hi] = [cuts[k], cuts[k + 1]];
    const piece = integrate(
      (s) => {
        const q = 1 - s;
        return integrand(hi - (hi - lo) * q * q * q, 3 * q * q * (hi - lo));
      },
      0,
      1,
      tol / (cuts.length - 1),
      2,
    );
    scale += piece[0];
    bias += piece[1];
  }
  return [scale, bias];
}

/**
 * The split-sum DFG term (Karis 2013): ∫ f(l, v)(n·l) dω = F0·scale + bias for Schlick's F, as [scale, bias],
 * since F = F0 (1 - Fc) + Fc with Fc = (1 - v·h)^5. `terms`: { ndf: 'ggx' | 'beckmann', visibility: a key of
 * VISIBILITY_TERMS }, both with roughness alpha (default GGX + height-correlated Smith). Adaptive to ~1e-7
 * unless `nodes` asks for a fixed Gauss-Legendre rule of that many nodes on every piece (faster, for tables).
 *
 * Deterministic quadrature over the microfacet normal m, l = reflect(v, m): with dω_l = 4 (v·m) dω_m,
 *   E = ∫ F V (n·l)(v·m)/(n·m) · D(m)(n·m) dω_m = (1/π) ∫_0^1 2r dr ∫_0^φmax F V (n·l)(v·m)/(n·m) dφ
 * in the variable r above (even in φ). l is above the horizon iff cos φ > cot θv (tan²θm - 1)/(2 tan θm), so
 * φmax is π for θm < θ1 = (π/2 - θv)/2, 0 beyond θ2 = (π/2 + θv)/2, and acos of that between: the r integral
 * is cut at θ1 and θ2 (and at the kinks of V), where it has kinks, and each piece goes to Gauss-Kronrod. No
 * cap: terms that do not conserve energy (e.g. a V that does not match the D) may give more than 1. `fresnel`
 * (a function of v·h) in place of the split gives [∫ F f_(F=1) (n·l) dω, 0]: the albedo with that Fresnel.
 */
export function dfgSplitSum(mu, alpha, terms = {}, { nodes = 0, fresnel = null } = {}) {
  const { ndf, visibility } = { ...DFG_DEFAULT_TERMS, ...terms };
  const tan2 = NDF_TAN2[ndf];
  const vis = VISIBILITY_TERMS[visibility];
  if (!tan2 || !vis) throw new Error(`dfgSplitSum: no split sum for D = ${ndf}, V = ${visibility}`);
  const a = clampAlpha(alpha);
  const a2 = a * a;
  const nv = Math.min(Math.max(mu, MU_MIN), 1);
  const sv = Math.sqrt((1 - nv) * (1 + nv));
  const kinks = VISIBILITY_KINKS[visibility] ?? [];
  const integrate = nodes ? (f, lo, hi, tol, dim) => gaussLegendreVector(f, lo, hi, nodes, dim) : integrateVector;
  const context = { nv, sv, vis, kinks, params: { alpha: a }, integrate, fresnel };
  const overPhi = (r) => {
    // r = 0 is θm = 90°, where the weight 2r vanishes; Beckmann's cuts underflow to r = 0 at small alpha
    if (!(r > 0)) return [0, 0];
    const t2 = tan2(r, a2);
    const cm = 1 / Math.sqrt(1 + t2);
    const sm = Math.sqrt(t2) * cm;
    const c = (nv * (t2 - 1)) / (2 * sv * Math.sqrt(t2)); // cos φmax (±Inf or NaN only outside (θ1, θ2))
    const phiMax = c <= -1 ? Math.PI : c >= 1 ? 0 : Math.acos(c);
    const sum = phiIntegral(context, cm, sm, phiMax, PHI_TOL / (2 * r)); // the tolerance of what the r integral adds
    return [2 * r * sum[0], 2 * r * sum[1]];
  };
  // tan θ1 = μ/(1 + sin θv) and tan θ2 = (1 + sin θv)/μ, by the half-angle tangent
  const rOf = (tanTheta) => NDF_R[ndf](tanTheta * tanTheta, a2);
  const theta2 = Math.atan((1 + sv) / nv);
  const cuts = [
    ...new Set([
      rOf((1 + sv) / nv),
      rOf(nv / (1 + sv)),
      1,
      ...kinkAngles(kinks, nv, sv, theta2).map((t) => rOf(Math.tan(t))),
    ]),
  ].sort((x, y) => x - y);
  const sum = [0, 0];
  for (let k = 0; k + 1 < cuts.length; k++) {
    const piece = smoothedIntegral(integrate, overPhi, cuts[k], cuts[k + 1], R_TOL / (cuts.length - 1));
    sum[0] += piece[0];
    sum[1] += piece[1];
  }
  return [sum[0] / Math.PI, sum[1] / Math.PI];
}

/** Texels per side of the DFG table the GPU samples (src/lab/dfg-table.js builds it). */
export const DFG_TABLE_SIZE = 72;

/**
 * Texture coordinates of (n·v, alpha) in the DFG table, texel centres edge to edge. Across: sqrt(n·v) plus a
 * share of the texels around n·v ~ 4 alpha, where the split sum turns at grazing view, so that the texels follow
 * that ridge from row to row; down: alpha^(1/3). Sampled bilinearly from half floats the table stays within
 * 1e-3 of dfgSplitSum for n·v in [1e-3, 1], alpha in [0.01, 1] (tests/unit/dfg-table.test.js).
 */
export function dfgTableUv(nv, alpha) {
  const n = DFG_TABLE_SIZE;
  const mu = Math.min(Math.max(nv, 0), 1);
  const a = Math.min(Math.max(alpha, 0), 1);
  const k = 4 * Math.max(a, ALPHA_MIN);
  const x = (Math.sqrt(mu) + (0.5 * mu) / (mu + k)) / (1 + 0.5 / (1 + k));
  return [(x * (n - 1) + 0.5) / n, (Math.cbrt(a) * (n - 1) + 0.5) / n];
}

/** Directional albedo with F = 1 (the white furnace): the split sum's scale + bias, for the same terms and options. */
export function albedoGGX(mu, alpha, terms = {}, options = {}) {
  const [scale, bias] = dfgSplitSum(mu, alpha, terms, options);
  return scale + bias;
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
