// Normal distribution functions D(m), in 1/sr, as functions of cosThetaM = n·m.
// D is a density over the hemisphere that satisfies ∫ D(m)(n·m) dω = 1. D = 0 for n·m <= 0.

/** Smallest roughness the functions accept; alpha is clamped to [ALPHA_MIN, 1]. */
export const ALPHA_MIN = 1e-4;
export const clampAlpha = (alpha) => Math.min(Math.max(alpha, ALPHA_MIN), 1);

/**
 * Trowbridge-Reitz (GGX): alpha² / (pi ((n·m)²(alpha² - 1) + 1)²).
 * The denominator is rewritten as alpha² c² + (1 - c)(1 + c): the textbook form adds 1 to a number
 * near -1 and cancels to 0 in float32 once alpha² drops below float32's epsilon (alpha < ~3e-4).
 */
export function ndfGGX(cosThetaM, alpha) {
  if (!(cosThetaM > 0)) return 0;
  const c = Math.min(cosThetaM, 1);
  const a = clampAlpha(alpha);
  const d = a * a * c * c + (1 - c) * (1 + c);
  const t = a / d;
  return (t * t) / Math.PI;
}
