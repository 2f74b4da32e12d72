// Visibility terms in the talk's convention V = G / ((n·l)(n·v)), so the microfacet BRDF is F·D·V / 4.
// V = 0 when n·l <= 0 or n·v <= 0 (the BRDF is zero at and below the horizon).
import { clampAlpha } from './ndf.js';

/**
 * Height-correlated Smith for GGX (Heitz 2014, eq. 99):
 *   V = 2 / (nv·sqrt(nl² + alpha²(1 - nl²)) + nl·sqrt(nv² + alpha²(1 - nv²))).
 */
export function visibilitySmithGGXCorrelated(nl, nv, alpha) {
  if (!(nl > 0 && nv > 0)) return 0;
  const l = Math.min(nl, 1);
  const v = Math.min(nv, 1);
  const a2 = clampAlpha(alpha) ** 2;
  const lambdaV = l * Math.sqrt(v * v + a2 * (1 - v) * (1 + v));
  const lambdaL = v * Math.sqrt(l * l + a2 * (1 - l) * (1 + l));
  return 2 / (lambdaV + lambdaL);
}
