// Normal distribution functions D(m), in 1/sr, as functions of cosThetaM = n·m.
// Each is a density of microfacet normals normalised so that ∫ D(m)(n·m) dω = 1 over the hemisphere,
// and is 0 for n·m <= 0. tan² and sin² are formed as (1 - c)(1 + c) [/ c²], never as 1 - c², so nothing
// cancels near c = 1 in float32; exponentials that underflow return 0 before 0·Inf can make a NaN.
import { PARAMETERS } from './catalogue/parameters.js';

/** Smallest roughness the functions accept; alpha is clamped to [ALPHA_MIN, 1] (the shared parameter table's). */
export const ALPHA_MIN = PARAMETERS.alpha.min;
export const clampAlpha = (alpha) => Math.min(Math.max(alpha, ALPHA_MIN), PARAMETERS.alpha.max);

const sin2 = (c) => (1 - c) * (1 + c);

/**
 * Trowbridge-Reitz (GGX): alpha² / (pi ((n·m)²(alpha² - 1) + 1)²).
 * The denominator is rewritten as alpha² c² + (1 - c)(1 + c): the textbook form adds 1 to a number
 * near -1 and cancels to 0 in float32 once alpha² drops below float32's epsilon (alpha < ~3e-4).
 */
export function ndfGGX(cosThetaM, alpha) {
  return ndfGGXFromSin2(cosThetaM, sin2(Math.min(cosThetaM, 1)), alpha);
}

/**
 * GGX with sin²θm given as well. From a half vector h in the local frame, sin² = h.x² + h.y² keeps its
 * relative precision however small θm is, where 1 - c² (or (1 - c)(1 + c) from a rounded c) cannot:
 * in float32 a direction within 3e-4 rad of n has c = 1 exactly.
 */
export function ndfGGXFromSin2(cosThetaM, sin2ThetaM, alpha) {
  if (!(cosThetaM > 0)) return 0;
  const c = Math.min(cosThetaM, 1);
  const a = clampAlpha(alpha);
  const d = a * a * c * c + Math.max(sin2ThetaM, 0);
  const t = a / d;
  return (t * t) / Math.PI;
}

/**
 * Normalised Blinn-Phong: (p + 2)/(2 pi) (n·m)^p for any exponent p >= 0 a double holds (Infinity counts as
 * the largest). The lobe is about sqrt(2/p) wide: from n·m alone a double resolves it up to p ~ 1e15; with
 * sin²θm given (ndfBlinnPhongFromSin2) up to p ~ 1e300, Walter's p = 2e8 at alpha = 1e-4 included.
 */
export function ndfBlinnPhong(cosThetaM, exponent) {
  return ndfBlinnPhongFromSin2(cosThetaM, sin2(Math.min(cosThetaM, 1)), exponent);
}

/**
 * Blinn-Phong with sin²θm given as well: ln (n·m)^p = (p/2) ln(1 - sin²θm), with log1p near n, where
 * sin² keeps its digits however narrow the lobe, and ln(n·m) away from it (where 1 - sin² may round to 0).
 */
export function ndfBlinnPhongFromSin2(cosThetaM, sin2ThetaM, exponent) {
  if (!(cosThetaM > 0)) return 0;
  const p = Math.min(Math.max(exponent, 0), Number.MAX_VALUE);
  const s2 = Math.max(sin2ThetaM, 0);
  const lnC = s2 < 0.5 ? Math.log1p(-s2) / 2 : Math.log(Math.min(cosThetaM, 1));
  return ((p + 2) / (2 * Math.PI)) * Math.exp(p * lnC);
}

/** Beckmann: exp(-tan²/alpha²) / (pi alpha² (n·m)^4). */
export function ndfBeckmann(cosThetaM, alpha) {
  return ndfBeckmannFromSin2(cosThetaM, sin2(Math.min(cosThetaM, 1)), alpha);
}

/** Beckmann with sin²θm given as well (see ndfGGXFromSin2). */
export function ndfBeckmannFromSin2(cosThetaM, sin2ThetaM, alpha) {
  if (!(cosThetaM > 0)) return 0;
  const c = Math.min(cosThetaM, 1);
  const a2 = clampAlpha(alpha) ** 2;
  const e = Math.max(sin2ThetaM, 0) / (c * c * a2);
  if (e > 80) return 0; // exp(-80) ~ 2e-35: underflows float32 before c^4 does
  const c2 = c * c;
  return Math.exp(-e) / (Math.PI * a2 * c2 * c2);
}

/** (e^x - 1)/x without cancellation near x = 0. */
function expm1OverX(x) {
  return Math.abs(x) < 1e-2 ? 1 + x / 2 + (x * x) / 6 + (x * x * x) / 24 : Math.expm1(x) / x;
}

const ABC_SERIES_TERMS = 40;

/**
 * Normalisation integral of the ABC distribution: I = ∫_0^1 (1 - u)(1 + a1 u)^-a2 du, so that
 * D = (1 + a1(1 - c))^-a2 / (2 pi I). With t = 1 + a1 u and L = ln(1 + a1):
 *   I = L [ (1 + a1) φ((1 - a2) L) - φ((2 - a2) L) ] / a1²,  φ(x) = (e^x - 1)/x,
 * which holds for every a2 (including 1 and 2, where the textbook antiderivative has logs). Its two terms
 * cancel as a1 -> 0, so there the binomial series is used: I = Σ_k C(-a2, k) a1^k / ((k + 1)(k + 2)),
 * whose terms shrink at least geometrically by a1 (a2 + 1) <= 1.
 */
export function abcNormalization(a1, a2) {
  if (a1 * (a2 + 1) <= 1) {
    let term = 1;
    let sum = 0;
    for (let k = 0; k < ABC_SERIES_TERMS; k++) {
      sum += term / ((k + 1) * (k + 2));
      term *= (-(a2 + k) * a1) / (k + 1);
    }
    return sum;
  }
  const L = Math.log1p(a1);
  return (L * ((1 + a1) * expm1OverX((1 - a2) * L) - expm1OverX((2 - a2) * L))) / (a1 * a1);
}

/** Parameter ranges the ABC functions accept (clamped): a1 in [0.01, 1e4], a2 in [0.05, 20]. */
export const clampAbc = (a1, a2) => [Math.min(Math.max(a1, 0.01), 1e4), Math.min(Math.max(a2, 0.05), 20)];

/**
 * The ABC distribution of Low et al. 2012 as the talk writes it, 1/(1 + a1(1 - n·m))^a2, made a density
 * (the talk's form is not normalised).
 */
export function ndfABC(cosThetaM, a1, a2) {
  if (!(cosThetaM > 0)) return 0;
  const [b, cc] = clampAbc(a1, a2);
  const c = Math.min(cosThetaM, 1);
  return (1 + b * (1 - c)) ** -cc / (2 * Math.PI * abcNormalization(b, cc));
}

/** Parameter ranges of the SGD functions (clamped): alpha in [0.01, 2], p in [0, 1.9]. */
export const clampSgd = (alpha, p) => [Math.min(Math.max(alpha, 0.01), 2), Math.min(Math.max(p, 0), 1.9)];

const SGD_STEPS = 48; // Simpson intervals: relative error below 1e-6 over the parameter range (see tests)

/**
 * ∫_alpha^∞ e^-y y^-p dy (the upper incomplete gamma Γ(1 - p, alpha)), as ∫_0^U e^-y y^(1-p) du with
 * y = alpha e^u: smooth, decaying like exp(-e^u), so Simpson's rule on a fixed grid is accurate.
 */
export function sgdNormalization(alpha, p) {
  const U = Math.log(50 / alpha); // e^-50 is far below what matters
  const h = U / SGD_STEPS;
  let sum = 0;
  for (let i = 0; i <= SGD_STEPS; i++) {
    const y = alpha * Math.exp(i * h);
    const w = i === 0 || i === SGD_STEPS ? 1 : i % 2 ? 4 : 2;
    sum += w * Math.exp(-y) * y ** (1 - p);
  }
  return (sum * h) / 3;
}

/**
 * Shifted gamma distribution (Bagher, Soler, Holzschuch 2012): D = P22(tan²) / (pi (n·m)^4) with
 * P22(x) = e^-y y^-p / (alpha Γ(1 - p, alpha)), y = alpha + x/alpha, normalised so ∫ P22 dx = 1. `norm`, the
 * normaliser Γ(1 - p, alpha), depends on the parameters alone: a caller evaluating many angles computes it once
 * (the catalogue's normaliser), as the GPU takes it (uSgdNorm, ndf.glsl).
 */
export function ndfSGD(cosThetaM, alpha, p, norm = sgdNormalization(...clampSgd(alpha, p))) {
  if (!(cosThetaM > 0)) return 0;
  const [a, q] = clampSgd(alpha, p);
  const c = Math.min(cosThetaM, 1);
  const c2 = c * c;
  const y = a + sin2(c) / (c2 * a);
  if (y > 80) return 0;
  return (Math.exp(-y) * y ** -q) / (a * norm * Math.PI * c2 * c2);
}

/** Walter et al. 2007: the Blinn-Phong exponent whose lobe matches a Beckmann alpha, p = 2/alpha² - 2. */
export function blinnPhongExponentFromBeckmannAlpha(alpha) {
  return Math.max(2 / clampAlpha(alpha) ** 2 - 2, 0);
}

export function beckmannAlphaFromBlinnPhongExponent(exponent) {
  return clampAlpha(Math.sqrt(2 / (Math.max(exponent, 0) + 2)));
}
