import { describe, expect, it } from 'vitest';
import {
  diffuseAshikhminShirley,
  diffuseFresnelWeighted,
  diffuseLambert,
  diffuseOrenNayar,
  diffuseOrenNayarQualitative,
} from '../../src/math/diffuse.js';
import { projectedNdfIntegral } from '../support/integration-helpers.js';

// albedo of a diffuse term at view cosine nv: ∫ f (n·l) dω over l, for terms that depend on n·l (and n·v)
// only, = 2 pi ∫_0^1 f(c) c dc (the Oren-Nayar azimuth is averaged separately below)
const albedo = (f) => projectedNdfIntegral(f);

describe('diffuse terms', () => {
  it('Lambert reflects exactly c_diff', () => {
    expect(albedo(() => diffuseLambert(0.7))).toBeCloseTo(0.7, 6);
  });
  it('Oren-Nayar, full and simplified, is Lambert at sigma = 0', () => {
    for (const [nl, nv, cp] of [
      [0.3, 0.9, 1],
      [0.7, 0.2, -0.5],
      [1, 1, 0],
    ]) {
      expect(diffuseOrenNayar(nl, nv, cp, 0, 0.6)).toBeCloseTo(diffuseLambert(0.6), 14);
      expect(diffuseOrenNayarQualitative(nl, nv, cp, 0, 0.6)).toBeCloseTo(diffuseLambert(0.6), 14);
    }
  });
  it('every diffuse term is reciprocal', () => {
    for (const [nl, nv] of [
      [0.2, 0.9],
      [0.5, 0.6],
      [0.95, 0.05],
    ]) {
      for (const cp of [-1, 0, 0.7]) {
        expect(diffuseOrenNayar(nl, nv, cp, 0.5, 0.8)).toBeCloseTo(diffuseOrenNayar(nv, nl, cp, 0.5, 0.8), 12);
        expect(diffuseOrenNayarQualitative(nl, nv, cp, 0.5, 0.8)).toBeCloseTo(
          diffuseOrenNayarQualitative(nv, nl, cp, 0.5, 0.8),
          12,
        );
      }
      expect(diffuseFresnelWeighted(nl, nv, 0.04, 0.8)).toBeCloseTo(diffuseFresnelWeighted(nv, nl, 0.04, 0.8), 14);
      expect(diffuseAshikhminShirley(nl, nv, 0.04, 0.8)).toBeCloseTo(diffuseAshikhminShirley(nv, nl, 0.04, 0.8), 14);
    }
  });
  it('the trade-off variants never reflect more than Lambert, and vanish at grazing', () => {
    for (const nv of [0.1, 0.5, 1]) {
      const fw = albedo((c) => diffuseFresnelWeighted(c, nv, 0.04, 1));
      const as = albedo((c) => diffuseAshikhminShirley(c, nv, 0.04, 1));
      expect(fw).toBeLessThanOrEqual(1);
      // Ashikhmin-Shirley: at most c_diff (1 - f0), so diffuse + specular <= 1
      expect(as).toBeLessThanOrEqual(1 - 0.04);
    }
    expect(diffuseFresnelWeighted(1e-9, 0.5, 0.04, 1)).toBeLessThan(1e-6);
  });
  it(
    'Fresnel-weighted Lambert is unnormalised: ' + 'head-on albedo (1 − F0)² (20/21) c_diff = 0.878 c_diff at F0 0.04',
    () => {
      // closed form: (1 − F(1)) · 2∫(1 − F(c)) c dc with Schlick F, 2∫(1 − c)⁵ c dc = 1/21; against quadrature
      const f0 = 0.04;
      const closed = (1 - f0) ** 2 * (20 / 21);
      expect(closed).toBeCloseTo(0.878, 3);
      expect(albedo((c) => diffuseFresnelWeighted(c, 1, f0, 1))).toBeCloseTo(closed, 6);
      // Shirley et al. 1997 scale the same shape by 21/20 and one (1 − F0): head-on they return (1 − F0) c_diff
      const shirley = albedo((c) => (diffuseFresnelWeighted(c, 1, f0, 1) * (21 / 20)) / (1 - f0));
      expect(shirley).toBeCloseTo(1 - f0, 6);
    },
  );
  it('the qualitative Oren-Nayar stays close to the full model without its inter-reflection term', () => {
    // the full model adds L2 (light bounced between V-grooves) and C3; for moderate sigma and angles
    // the two agree within 15%
    for (const [nl, nv, cp] of [
      [0.8, 0.8, 1],
      [0.6, 0.9, 0.5],
      [0.9, 0.5, 1],
    ]) {
      const full = diffuseOrenNayar(nl, nv, cp, 0.3, 0.5);
      const simple = diffuseOrenNayarQualitative(nl, nv, cp, 0.3, 0.5);
      expect(Math.abs(simple / full - 1)).toBeLessThan(0.15);
    }
  });
  it('flattens a rough sphere seen with the light behind the viewer (the full-moon look)', () => {
    // l = v (cos phi = 1): radiance f (n·l) at the limb, relative to the centre, is much higher than Lambert's
    const limb = 0.2;
    const lambertRatio = limb; // f constant: radiance ∝ n·l
    const onRatio = (diffuseOrenNayar(limb, limb, 1, 1, 0.8) * limb) / diffuseOrenNayar(1, 1, 1, 1, 0.8);
    expect(onRatio).toBeGreaterThan(2 * lambertRatio);
  });
});
