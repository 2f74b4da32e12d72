// Fresnel reflectance: Schlick's approximation and the exact equations for dielectrics and conductors.
// Inputs are cosines (cosTheta = n·l, or l·h inside a microfacet BRDF); they are clamped to [0, 1].
// Every form below is written so that no difference of nearly equal numbers is taken:
// sin² = (1 - c)(1 + c), eta² - 1 = (eta - 1)(eta + 1), and g - c is rewritten as (g² - c²)/(g + c).

const clamp01 = (x) => Math.min(Math.max(x, 0), 1);

/** Schlick 1994: f0 + (1 - f0)(1 - cosTheta)^5. */
export function fresnelSchlick(f0, cosTheta) {
  const m = 1 - clamp01(cosTheta);
  const m2 = m * m;
  return f0 + (1 - f0) * m2 * m2 * m;
}

/**
 * Schlick with the fifth power replaced by a spherical-Gaussian fit, 2^((-5.55473 c - 6.98316) c)
 * (Karis 2013, "Real Shading in Unreal Engine 4", after Lagarde): one exp2 instead of a power.
 */
export function fresnelSchlickSG(f0, cosTheta) {
  const c = clamp01(cosTheta);
  return f0 + (1 - f0) * 2 ** ((-5.55473 * c - 6.98316) * c);
}

/** Normal-incidence reflectance of an interface with relative IOR eta (and extinction k, 0 for dielectrics). */
export function f0FromIor(eta, k = 0) {
  return ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
}

/** Inverse of f0FromIor for a dielectric with eta >= 1. f0 is clamped to [0, 0.999]. */
export function iorFromF0(f0) {
  const s = Math.sqrt(Math.min(Math.max(f0, 0), 0.999));
  return (1 + s) / (1 - s);
}

/**
 * Exact unpolarized Fresnel reflectance of a dielectric interface, eta = n_t / n_i > 0.
 * With g = eta·cos(theta_t) = sqrt(eta² - 1 + c²) the amplitude ratios are
 *   r_s = -(eta² - 1) / (g + c)²,   r_p = (eta² - 1)((eta² + 1)c² - 1) / (eta² c + g)²,
 * both proportional to eta² - 1, so eta -> 1 gives 0 without cancellation.
 * Total internal reflection (g² < 0) gives 1. eta = 1 exactly (no interface) gives 0.
 */
export function fresnelDielectric(cosThetaI, eta) {
  const c = clamp01(cosThetaI);
  const e2m1 = (eta - 1) * (eta + 1);
  if (e2m1 === 0) return 0;
  const g2 = e2m1 + c * c;
  if (g2 <= 0) return 1;
  const g = Math.sqrt(g2);
  const rs = -e2m1 / ((g + c) * (g + c));
  const pd = eta * eta * c + g;
  const rp = (e2m1 * ((eta * eta + 1) * c * c - 1)) / (pd * pd);
  return Math.min(0.5 * (rs * rs + rp * rp), 1);
}

/**
 * Exact unpolarized Fresnel reflectance of a conductor with complex IOR eta + i·k (relative to the outside).
 * Standard form (e.g. Born & Wolf; Lagarde 2013, "Memo on Fresnel equations") with
 *   a² + b² = s = sqrt(x² + 4 eta² k²),  x = eta² - k² - sin²,  a² = (s + x) / 2,  b² = (s - x) / 2,
 *   R_s = ((a - c)² + b²) / ((a + c)² + b²),
 *   R_p = R_s · ((a c - sin²)² + b² c²) / ((a c + sin²)² + b² c²).
 * a² and b² are taken from whichever of s + x, s - x does not cancel, and a - c = (a² - c²)/(a + c),
 * so k = 0 reduces to fresnelDielectric (total internal reflection included) at full precision.
 */
export function fresnelConductor(cosThetaI, eta, k) {
  const c = clamp01(cosThetaI);
  const c2 = c * c;
  const sin2 = (1 - c) * (1 + c);
  const e2m1 = (eta - 1) * (eta + 1);
  const ek2 = 4 * eta * eta * k * k;
  const x = e2m1 - k * k + c2;
  const s = Math.sqrt(x * x + ek2);
  let a2, b2, a2mc2;
  if (x > 0) {
    b2 = ek2 / (2 * (s + x));
    a2 = x + b2;
    a2mc2 = e2m1 - k * k + b2;
  } else {
    a2 = s - x > 0 ? ek2 / (2 * (s - x)) : 0;
    b2 = a2 - x;
    a2mc2 = a2 - c2;
  }
  const a = Math.sqrt(a2);
  const amc = a + c > 0 ? a2mc2 / (a + c) : 0;
  const sDen = (a + c) * (a + c) + b2;
  if (sDen === 0) return 0; // eta = 1, k = 0 at grazing: no interface
  const rs = (amc * amc + b2) / sDen;
  const ac = a * c;
  const pNum = (ac - sin2) * (ac - sin2) + b2 * c2;
  const pDen = (ac + sin2) * (ac + sin2) + b2 * c2;
  const rp = pDen > 0 ? (rs * pNum) / pDen : rs;
  return Math.min(0.5 * (rs + rp), 1);
}

// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel", JCGT 3(4): a conductor's (n, k) from its
// normal-incidence reflectance r and an edge tint g in [0, 1]. r is clamped below 1 (r = 1 has no finite n).
const R_MAX = 0.999;
const nMin = (r) => (1 - r) / (1 + r);
const nMax = (r) => (1 + Math.sqrt(r)) / (1 - Math.sqrt(r));

/** (n, k) that reproduce reflectance r at normal incidence, with edge tint g. */
export function conductorIorFromF0EdgeTint(r, g) {
  const rc = Math.min(Math.max(r, 0), R_MAX);
  const gc = Math.min(Math.max(g, 0), 1);
  const n = gc * nMin(rc) + (1 - gc) * nMax(rc);
  const k2 = (rc * (n + 1) * (n + 1) - (n - 1) * (n - 1)) / (1 - rc);
  return [n, Math.sqrt(Math.max(k2, 0))];
}

/** The edge tint g that, with r = f0FromIor(n, k), maps back to (n, k). */
export function edgeTintFromConductorIor(n, k) {
  const r = Math.min(f0FromIor(n, k), R_MAX);
  const span = nMax(r) - nMin(r);
  return span > 0 ? (nMax(r) - n) / span : 0; // r = 0 (n = 1, k = 0): every tint maps to n = 1
}

// F82-tint: Schlick with a dip near grazing, as metals have it. Hoffman 2019, "Fresnel Equations Considered
// Harmful" (Eurographics MAM workshop) and Hoffman 2023, "Generalization of Adobe's Fresnel Model"; the metal
// Fresnel of Adobe's Standard Material (Kutz, Hašan & Edmondson 2021) and of OpenPBR Surface (ASWF 2024, "Metal"):
//   F(μ) = Schlick(f0, μ) − b μ (1 − μ)⁶,   b = Schlick(f0, μ̄)(1 − tint) / (μ̄ (1 − μ̄)⁶),   μ̄ = 1/7,
// so F(μ̄) = tint · Schlick(f0, μ̄): the tint (OpenPBR's specular_color for a metal) is the share of Schlick's
// value kept at θ = acos(1/7) ≈ 81.8°, near where a metal's curve dips most below Schlick's.

/** μ̄ = cos θ̄ = 1/7, θ̄ ≈ 81.8°: the angle at which F82-tint's tint is defined. */
export const F82_MU = 1 / 7;
const F82_NORM = 7 ** 7 / 6 ** 6; // 1 / (μ̄ (1 − μ̄)⁶), exactly 823543 / 46656

/**
 * F82-tint Fresnel of one channel. f0 and tint are clamped to [0, 1] (MaterialX's mx_init_fresnel_schlick does the
 * same). Departure: the result is clamped to [0, 1]. With a small tint the formula dips below 0 around μ̄ and at mid
 * angles (tint below 0.51 at f0 = 0, below 0.03 at f0 = 0.5; down to −0.127 at f0 = tint = 0); MaterialX leaves it
 * negative. The metals of the talk's table have tints of 0.77 and more.
 */
export function fresnelF82Tint(f0, tint, cosTheta) {
  const f = clamp01(f0);
  const c = clamp01(cosTheta);
  const m = 1 - c;
  const m3 = m * m * m;
  const b = fresnelSchlick(f, F82_MU) * (1 - clamp01(tint)) * F82_NORM;
  return clamp01(fresnelSchlick(f, c) - b * c * m3 * m3);
}

/**
 * { f0, tint } of F82-tint fitted to a conductor (eta + i k, relative to the outside) with the exact Fresnel
 * equations: f0 = F(1) and tint = F(μ̄) / Schlick(f0, μ̄), so F82-tint meets the exact curve at θ = 0 and at
 * θ = acos(1/7). The tint may exceed 1 for an interface whose curve rises above Schlick's at 81.8°; then F82-tint,
 * whose tint is a colour in [0, 1], cannot follow it.
 */
export function f82TintFromConductor(eta, k) {
  const f0 = fresnelConductor(1, eta, k);
  return { f0, tint: fresnelConductor(F82_MU, eta, k) / fresnelSchlick(f0, F82_MU) };
}
