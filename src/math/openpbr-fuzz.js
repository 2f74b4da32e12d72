// OpenPBR Surface's fuzz lobe: the specification's reference (v1.1.1, "Fuzz"), Zeltner, Burley & Chiang 2022,
// "Practical Multiple-Scattering Sheen Using Linearly Transformed Cosines": a volumetric layer of fibre-like SGGX
// microflakes of unit optical depth, its multiply scattered reflection fitted by an LTC lobe D(l | n·v, r) and an
// albedo R(n·v, r):  (n·l) f = R(n·v, r) D(l).  The coefficients are MaterialX 1.39's rational fits to the paper's
// tables (libraries/pbrlib/genglsl/lib/mx_microfacet_sheen.glsl, mx_zeltner_sheen_*), which its open_pbr_surface
// uses (sheen_bsdf, mode "zeltner"); the roughness is clamped to [0.01, 1] as there. The lobe is built around v:
// it is not reciprocal (f(l, v) ≠ f(v, l)), as the paper's is not.

const clamp = (x, lo, hi) => Math.min(Math.max(x, lo), hi);
const FUZZ_ROUGHNESS_MIN = 0.01;
const MU_MIN = 1e-7; // n·v below this is taken as this (the fits divide by nothing but are fitted on (0, 1])

/** R(μ, r): the fuzz layer's directional albedo (fuzz_color = 1), a Gaussian in μ plus an offset, per r; ≥ 0. */
export function albedoFuzzZeltner(mu, roughness) {
  const x = clamp(mu, MU_MIN, 1);
  const y = clamp(roughness, FUZZ_ROUGHNESS_MIN, 1);
  const s = (y * (0.0206607 + 1.58491 * y)) / (0.0379424 + y * (1.32227 + y));
  const m = (y * (-0.193854 + y * (-1.14885 + y * (1.7932 - 0.95943 * y * y)))) / (0.046391 + y);
  const o = (y * (0.000654023 + (-0.0207818 + 0.119681 * y) * y)) / (1.26264 + y * (-1.92021 + y));
  const z = (x - m) / s;
  // the fit dips to -4e-6 at r = 0.01, n·v = 1: held at 0, so that the lobe is never negative
  return Math.max(Math.exp(-0.5 * z * z) / (s * Math.sqrt(2 * Math.PI)) + o, 0);
}

/** The LTC's inverse matrix [[aInv, 0, bInv], [0, aInv, 0], [0, 0, 1]], fitted per (n·v, r). */
function ltcInverse(mu, roughness) {
  const x = clamp(mu, MU_MIN, 1);
  const y = clamp(roughness, FUZZ_ROUGHNESS_MIN, 1);
  const aInv = ((2.58126 * x + 0.813703 * y) * y) / (1 + 0.310327 * x * x + 2.60994 * x * y);
  const bInv =
    (Math.sqrt(1 - x) * (y - 1) * y * y * y) / (0.0000254053 + 1.71228 * x - 1.71506 * x * y + 1.34174 * y * y);
  return [aInv, bInv];
}

/**
 * D(l): the LTC lobe's density per steradian over l (a pdf on the upper hemisphere), in the frame whose x axis
 * is v's azimuth (any, when v = n): D = (w'z/π)(aInv/|w'|²)² with w' = M⁻¹ l.
 */
export function ltcFuzzZeltner(l, v, roughness) {
  const [aInv, bInv] = ltcInverse(v[2], roughness);
  const sv = Math.hypot(v[0], v[1]);
  const [cx, cy] = sv > 0 ? [v[0] / sv, v[1] / sv] : [1, 0];
  const wx = l[0] * cx + l[1] * cy;
  const wy = -l[0] * cy + l[1] * cx;
  const w = [aInv * wx + bInv * l[2], aInv * wy, l[2]];
  if (!(w[2] > 0)) return 0;
  const len2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  return (w[2] / Math.PI) * (aInv / len2) ** 2;
}

/** The fuzz BRDF for fuzz_color = 1, in 1/sr: R(n·v, r) D(l) / (n·l); 0 below the horizon. */
export function fuzzZeltner(l, v, roughness) {
  if (!(l[2] > 0 && v[2] > 0)) return 0;
  return (albedoFuzzZeltner(v[2], roughness) * ltcFuzzZeltner(l, v, roughness)) / l[2];
}
