// Geometry and visibility terms, in the talk's convention V = G / ((n·l)(n·v)), so the microfacet BRDF is
// F·D·V / 4. Every V is 0 when n·l <= 0 or n·v <= 0 (the BRDF is zero at and below the horizon), and every
// G1 is in [0, 1] and 0 for cos <= 0. sin² is (1 - c)(1 + c) throughout.
import { clampAlpha } from './ndf.js';
import { erfc } from './special.js';

const above = (nl, nv) => nl > 0 && nv > 0;
const sin2 = (c) => (1 - c) * (1 + c);

/** No visibility term: V = 1, i.e. the implicit G = (n·l)(n·v). Cheaper than free; ignores roughness. */
export function visibilityImplicit(nl = 1, nv = 1) {
  return above(nl, nv) ? 1 : 0;
}

/** Cook-Torrance: min(1, 2(n·h)(n·v)/(v·h), 2(n·h)(n·l)/(v·h)) / ((n·l)(n·v)), divided term by term. */
export function visibilityCookTorrance(nl, nv, nh, vh) {
  if (!above(nl, nv) || !(vh > 0) || !(nh > 0)) return 0;
  return Math.min(1 / (nl * nv), (2 * nh) / (vh * nl), (2 * nh) / (vh * nv));
}

/** Kelemen & Szirmay-Kalos 2001: Cook-Torrance approximated by 1/(l·h)². */
export function visibilityKelemen(lh) {
  return lh > 0 ? 1 / (lh * lh) : 0;
}

/** sqrt(c² + alpha² sin²): the root in every Smith GGX form (c (1 + 2Λ) in Heitz's notation). */
const ggxRoot = (c, a2) => Math.sqrt(c * c + a2 * sin2(c));

/** Smith G1 for GGX: 2c / (c + sqrt(c² + alpha² sin²)). */
export function smithG1GGX(cosTheta, alpha) {
  if (!(cosTheta > 0)) return 0;
  const c = Math.min(cosTheta, 1);
  return (2 * c) / (c + ggxRoot(c, clampAlpha(alpha) ** 2));
}

/**
 * Smith G1 for Beckmann, exact: 1/(1 + Λ(a)), a = c/(alpha sin),
 * Λ(a) = (exp(-a²)/(a sqrt(pi)) - erfc(a)) / 2 (the same as (erf(a) - 1)/2 + exp(-a²)/(2a sqrt(pi))).
 */
/** Beckmann's a = cot(theta)/alpha for G1, or Infinity at normal incidence (where G1 = 1). */
function beckmannSlopeRatio(c, alpha) {
  const s2 = sin2(c);
  return s2 === 0 ? Infinity : c / (clampAlpha(alpha) * Math.sqrt(s2));
}

export function smithG1Beckmann(cosTheta, alpha) {
  if (!(cosTheta > 0)) return 0;
  const a = beckmannSlopeRatio(Math.min(cosTheta, 1), alpha);
  if (a > 26) return 1; // Λ < 1e-290
  const lambda = (Math.exp(-a * a) / (a * Math.sqrt(Math.PI)) - erfc(a)) / 2;
  return 1 / (1 + lambda);
}

/** Walter et al. 2007's rational fit to Beckmann's Smith G1 (max error ~0.35%). */
export function smithG1BeckmannWalter(cosTheta, alpha) {
  if (!(cosTheta > 0)) return 0;
  const a = beckmannSlopeRatio(Math.min(cosTheta, 1), alpha);
  return a < 1.6 ? Math.min((3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a), 1) : 1;
}

/** Separable Smith for GGX: G1(l)G1(v)/((n·l)(n·v)) = 4 / ((nl + sqrt(nl² + a² sl²))(nv + sqrt(nv² + a² sv²))). */
export function visibilitySmithGGXSeparable(nl, nv, alpha) {
  if (!above(nl, nv)) return 0;
  const l = Math.min(nl, 1);
  const v = Math.min(nv, 1);
  const a2 = clampAlpha(alpha) ** 2;
  return 4 / ((l + ggxRoot(l, a2)) * (v + ggxRoot(v, a2)));
}

/**
 * Height-correlated Smith for GGX (Heitz 2014, eq. 99):
 *   V = 2 / (nv·sqrt(nl² + alpha²(1 - nl²)) + nl·sqrt(nv² + alpha²(1 - nv²))).
 */
export function visibilitySmithGGXCorrelated(nl, nv, alpha) {
  if (!above(nl, nv)) return 0;
  const l = Math.min(nl, 1);
  const v = Math.min(nv, 1);
  const a2 = clampAlpha(alpha) ** 2;
  return 2 / (l * ggxRoot(v, a2) + v * ggxRoot(l, a2));
}

/** Hammon 2017's approximation of height-correlated GGX Smith: V = 2 / lerp(2 nl nv, nl + nv, alpha). */
export function visibilitySmithGGXCorrelatedFast(nl, nv, alpha) {
  if (!above(nl, nv)) return 0;
  const l = Math.min(nl, 1);
  const v = Math.min(nv, 1);
  const a = clampAlpha(alpha);
  return 2 / ((1 - a) * 2 * l * v + a * (l + v));
}

/** Schlick's G1 with Karis 2013's k = alpha/2 (Unreal Engine 4): V = 1/((nl(1-k)+k)(nv(1-k)+k)). */
export function visibilitySchlickGGX(nl, nv, alpha) {
  if (!above(nl, nv)) return 0;
  const k = clampAlpha(alpha) / 2;
  return 1 / ((Math.min(nl, 1) * (1 - k) + k) * (Math.min(nv, 1) * (1 - k) + k));
}

/** Separable Smith for Beckmann with the exact G1. */
export function visibilitySmithBeckmannSeparable(nl, nv, alpha) {
  if (!above(nl, nv)) return 0;
  return (smithG1Beckmann(nl, alpha) * smithG1Beckmann(nv, alpha)) / (Math.min(nl, 1) * Math.min(nv, 1));
}
