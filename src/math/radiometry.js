// The physics → math step of the talk: radiance along a ray, the irradiance a small lamp gives, and a
// spectrum reduced to the three numbers a renderer keeps (CIE 1931 XYZ, then linear sRGB).

/** Solid angle (sr) of a sphere of radius r seen from distance d ≥ r from its centre: 2π (1 − cos θs). */
export function sphereSolidAngle(radius, distance) {
  const s = Math.min(Math.max(radius, 0) / Math.max(distance, 1e-300), 1); // sin θs; inside the sphere: 1
  const s2 = s * s;
  return (2 * Math.PI * s2) / (1 + Math.sqrt(1 - s2)); // 2π(1 − cos θs), without the cancellation near s = 0
}

/**
 * Irradiance on a surface facing a sphere lamp of uniform radiance L, radius r, at distance d from its
 * centre: ∫ L cos θ dω over the sphere's cap = π L sin²θs = π L (r/d)² (exact for d ≥ r). The radiance in
 * every direction that meets the lamp stays L at any distance; the irradiance falls as 1/d².
 */
export function sphereLightIrradiance(radiance, radius, distance) {
  const s = Math.min(Math.max(radius, 0) / Math.max(distance, 1e-300), 1);
  return Math.PI * Math.max(radiance, 0) * s * s;
}

const H = 6.62607015e-34; // Planck constant, J s (SI 2019, exact)
const C = 299792458; // speed of light, m/s (exact)
const KB = 1.380649e-23; // Boltzmann constant, J/K (exact)

/** Planck's law: spectral radiance of a black body, W sr⁻¹ m⁻² nm⁻¹, at wavelength λ (nm) and T (K). */
export function planckRadiance(lambdaNm, kelvin) {
  if (!(lambdaNm > 0) || !(kelvin > 0)) return 0;
  const l = lambdaNm * 1e-9;
  const x = (H * C) / (l * KB * kelvin);
  if (x > 700) return 0; // e^x overflows: nothing emitted at this wavelength
  return ((2 * H * C * C) / l ** 5 / Math.expm1(x)) * 1e-9;
}

// Wyman, Sloan & Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
// JCGT 2(2): the multi-lobe fit to the CIE 1931 2° observer, a sum of piecewise Gaussians.
const lobe = (l, mu, s1, s2) => {
  const t = (l - mu) / (l < mu ? s1 : s2);
  return Math.exp(-0.5 * t * t);
};

/** CIE 1931 colour matching functions [x̄, ȳ, z̄] at λ (nm), by Wyman et al.'s multi-lobe fit. */
export function cieXyzFit(lambdaNm) {
  const l = lambdaNm;
  return [
    1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2),
    0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
    1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8),
  ];
}

/** XYZ of a spectrum S(λ) (a function of nm): ∫ S cmf dλ over 380–780 nm, midpoint rule with 1 nm steps. */
export function spectrumToXyz(spectrum) {
  const xyz = [0, 0, 0];
  for (let l = 380.5; l < 780; l += 1) {
    const s = spectrum(l);
    const cmf = cieXyzFit(l);
    for (let i = 0; i < 3; i++) xyz[i] += s * cmf[i];
  }
  return xyz;
}

/** XYZ → linear sRGB (IEC 61966-2-1, D65 white). Outside the gamut a channel is negative or above 1. */
export function xyzToLinearSrgb([x, y, z]) {
  return [
    3.2406 * x - 1.5372 * y - 0.4986 * z,
    -0.9689 * x + 1.8758 * y + 0.0415 * z,
    0.0557 * x - 0.204 * y + 1.057 * z,
  ];
}
