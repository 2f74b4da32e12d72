// Radiance along a ray and the irradiance of a small lamp, checked by quadrature; the spectrum → XYZ → sRGB
// chain checked against published colorimetry (CIE 15:2004 white points, IEC 61966-2-1) and Wien's law.
import { describe, expect, it } from 'vitest';
import {
  cieXyzFit,
  planckRadiance,
  spectrumToXyz,
  sphereLightIrradiance,
  sphereSolidAngle,
  xyzToLinearSrgb,
} from '../../src/math/radiometry.js';

/** ∫ over the lamp's cap (half angle θs) of g(θ) dω = 2π ∫_0^θs g(θ) sin θ dθ, midpoint rule. */
function capIntegral(thetaS, g, n = 20000) {
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const t = ((i + 0.5) / n) * thetaS;
    sum += g(t) * Math.sin(t);
  }
  return (2 * Math.PI * sum * thetaS) / n;
}

const chromaticity = ([x, y, z]) => [x / (x + y + z), y / (x + y + z)];

describe('radiance and irradiance', () => {
  it('a sphere lamp’s solid angle and irradiance equal the integrals over its cap (∫ dω, ∫ L cos θ dω)', () => {
    for (const [r, d] of [
      [0.05, 0.06],
      [0.05, 1],
      [0.05, 30],
      [1, 1],
    ]) {
      const thetaS = Math.asin(Math.min(r / d, 1));
      expect(sphereSolidAngle(r, d)).toBeCloseTo(
        capIntegral(thetaS, () => 1),
        7,
      );
      expect(sphereLightIrradiance(3, r, d)).toBeCloseTo(
        capIntegral(thetaS, (t) => 3 * Math.cos(t)),
        7,
      );
    }
  });
  it('radiance stays L with distance while the irradiance falls as 1/d² (inverse-square law)', () => {
    const [L, r] = [5, 0.05];
    for (const d of [1, 3, 10]) {
      expect(sphereLightIrradiance(L, r, 2 * d) / sphereLightIrradiance(L, r, d)).toBeCloseTo(0.25, 12);
      // irradiance / solid angle = mean L cos θ over the lamp → L as the lamp shrinks to a point
      expect(sphereLightIrradiance(L, r, d) / sphereSolidAngle(r, d)).toBeCloseTo(L, d >= 3 ? 3 : 2);
    }
  });
});

describe('a spectrum reduced to RGB', () => {
  it('the colour matching fit gives the equal-energy white (1/3, 1/3) and ∫ȳ dλ = 106.857 (CIE 1931, 2°)', () => {
    const xyz = spectrumToXyz(() => 1);
    const [x, y] = chromaticity(xyz);
    expect(Math.abs(x - 1 / 3)).toBeLessThan(0.001);
    expect(Math.abs(y - 1 / 3)).toBeLessThan(0.001);
    expect(Math.abs(xyz[1] / 106.857 - 1)).toBeLessThan(0.002);
    const peak = [...Array(400).keys()]
      .map((i) => 380 + i)
      .reduce((a, l) => (cieXyzFit(l)[1] > cieXyzFit(a)[1] ? l : a));
    expect(Math.abs(peak - 555)).toBeLessThanOrEqual(1);
  });
  it('a black body at 2856 K lands on CIE illuminant A (x 0.44757, y 0.40745, CIE 15:2004) within 0.002', () => {
    const [x, y] = chromaticity(spectrumToXyz((l) => planckRadiance(l, 2856)));
    expect(Math.abs(x - 0.44757)).toBeLessThan(0.002);
    expect(Math.abs(y - 0.40745)).toBeLessThan(0.002);
  });
  it('Planck’s law peaks where Wien’s displacement law says: λ = 2.897771955e-3 m K / T', () => {
    for (const T of [3000, 5000, 6500]) {
      let best = 0;
      for (let l = 300; l < 1200; l += 0.01) if (planckRadiance(l, T) > planckRadiance(best, T)) best = l;
      expect(best).toBeCloseTo(2.897771955e6 / T, 1);
    }
  });
  it('XYZ → linear sRGB maps the D65 white (0.95047, 1, 1.08883) to (1, 1, 1) (IEC 61966-2-1)', () => {
    for (const c of xyzToLinearSrgb([0.95047, 1, 1.08883])) expect(c).toBeCloseTo(1, 3);
  });
});
