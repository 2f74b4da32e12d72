// The split sum and the directional albedo (quadrature over the microfacet normal, src/math/integrate.js)
// against an independent quadrature over the LIGHT direction (integration-helpers.js) that evaluates the whole
// BRDF of src/math/brdf.js, and against closed forms and published values.
import { describe, expect, it } from 'vitest';
import { microfacetBRDF, VISIBILITY_TERMS } from '../../src/math/brdf.js';
import { albedoGGX, dfgSplitSum, directionFromCos } from '../../src/math/integrate.js';
import { albedoOverLight } from '../support/integration-helpers.js';
import { DEG } from '../../src/math/angles.js';

/** [scale, bias] by the light-direction quadrature: scale + bias with F = 1, bias with Schlick F0 = 0. */
function splitSumOverLight(mu, alpha, D, V, longest) {
  const v = directionFromCos(mu);
  const width = Math.min(2 * alpha, mu); // the lobe's width, or the mirror's distance to the horizon
  const f = (params) => (l) => microfacetBRDF(l, v, { D, V, alpha, ...params });
  const over = (params) => albedoOverLight(f(params), Math.acos(mu), width, longest);
  const albedo = over({ F: 'one' });
  const bias = over({ F: 'schlick', f0: 0 });
  return [albedo - bias, bias];
}

describe('split-sum DFG against a quadrature over the light direction', () => {
  const GRID_MUS = [1e-3, 0.01, 0.1, 0.3, 0.6, 0.9, 1];
  it.each(GRID_MUS)('GGX, height-correlated Smith: scale and bias within 1e-5 at mu = %f, alpha 0.01 to 1', (mu) => {
    for (const alpha of [0.01, 0.05, 0.2, 0.5, 1]) {
      const [scale, bias] = dfgSplitSum(mu, alpha);
      const [s, b] = splitSumOverLight(mu, alpha, 'ggx', 'smithGGXCorrelated');
      expect(Math.abs(scale - s), `scale at mu ${mu}, alpha ${alpha}`).toBeLessThan(1e-5);
      expect(Math.abs(bias - b), `bias at mu ${mu}, alpha ${alpha}`).toBeLessThan(1e-5);
    }
  });
  const smooth = Object.keys(VISIBILITY_TERMS).filter((V) => V !== 'cookTorrance');
  const pairs = ['ggx', 'beckmann'].flatMap((D) => smooth.map((V) => [D, V]));
  it.each(pairs)('D = %s, V = %s: albedo within 1e-5 at grazing, mid and normal view', (D, V) => {
    for (const [mu, alpha] of [
      [1e-3, 0.01],
      [1e-3, 1],
      [0.3, 0.3],
      [1, 0.05],
    ]) {
      const [s, b] = splitSumOverLight(mu, alpha, D, V);
      const albedo = albedoGGX(mu, alpha, { ndf: D, visibility: V });
      expect(Math.abs(albedo - (s + b)), `mu ${mu}, alpha ${alpha}`).toBeLessThan(1e-5);
    }
  });
  it('Beckmann at small alpha, where its cuts underflow to r = 0 (a NaN once): within 1e-5, for every V', () => {
    const [mu, alpha] = [0.6414, 0.00943]; // a texel of the shipped DFG tables
    for (const V of smooth) {
      const [s, b] = splitSumOverLight(mu, alpha, 'beckmann', V);
      const [scale, bias] = dfgSplitSum(mu, alpha, { ndf: 'beckmann', visibility: V });
      expect(Math.abs(scale - s), V).toBeLessThan(1e-5);
      expect(Math.abs(bias - b), V).toBeLessThan(1e-5);
    }
  });
  it("Cook-Torrance's min(): within 1e-5 with the light-direction pieces kept short (kinks fall inside them)", () => {
    const [s, b] = splitSumOverLight(0.1, 0.3, 'beckmann', 'cookTorrance', 0.02);
    expect(Math.abs(albedoGGX(0.1, 0.3, { ndf: 'beckmann', visibility: 'cookTorrance' }) - (s + b))).toBeLessThan(1e-5);
  });
  it('Cook-Torrance at normal incidence: within 1e-8 of a 1-D Simpson rule over θl (20000 steps)', () => {
    const p = { F: 'one', D: 'ggx', V: 'cookTorrance', alpha: 0.3 };
    const n = 20000;
    const h = Math.PI / 2 / n;
    let sum = 0;
    for (let i = 0; i <= n; i++) {
      const t = i * h;
      const g = microfacetBRDF([Math.sin(t), 0, Math.cos(t)], [0, 0, 1], p) * Math.cos(t) * Math.sin(t);
      sum += (i === 0 || i === n ? 1 : i % 2 ? 4 : 2) * g;
    }
    expect(albedoGGX(1, 0.3, { visibility: 'cookTorrance' })).toBeCloseTo((2 * Math.PI * sum * h) / 3, 8);
  });
  it('rejects terms it has no split sum for', () => {
    expect(() => dfgSplitSum(0.5, 0.5, { ndf: 'blinnPhong' })).toThrow(/no split sum/);
    expect(() => dfgSplitSum(0.5, 0.5, { visibility: 'smithGGX' })).toThrow(/no split sum/);
  });
});

describe('directional albedo: closed form and published values', () => {
  it('is 1 - ln 2 for GGX at alpha = 1 seen head on (closed form)', () => {
    expect(albedoGGX(1, 1)).toBeCloseTo(1 - Math.log(2), 9);
  });
  it('is 0.872 at 85° and alpha 0.5 (issue 11; 64 Hammersley samples gave 0.959)', () => {
    expect(albedoGGX(Math.cos(85 * DEG), 0.5)).toBeCloseTo(0.872, 3);
  });
  it('is 0.993 at mu = 0.001, alpha = 1, not capped at 1', () => {
    expect(albedoGGX(1e-3, 1)).toBeCloseTo(0.993, 3);
  });
  it('is 1/4 at every view for GGX at alpha = 1 with the implicit V (f = 1/4π, closed form)', () => {
    for (const mu of [1e-3, 0.3, 1]) expect(albedoGGX(mu, 1, { visibility: 'implicit' })).toBeCloseTo(0.25, 9);
  });
  it("is not capped at 1: GGX's D with Beckmann's Smith V (a mismatched pair) sends back 1.61 at grazing", () => {
    expect(albedoGGX(1e-3, 0.01, { visibility: 'smithBeckmannSeparable' })).toBeCloseTo(1.6124, 4);
  });
  it('with F0 = 1 the split sum F0·scale + bias is the F = 1 albedo, and with F0 = 0 it is the bias alone', () => {
    const v = directionFromCos(0.4);
    const brdf = (F, f0) => (l) => microfacetBRDF(l, v, { F, f0, D: 'ggx', V: 'smithGGXCorrelated', alpha: 0.4 });
    const over = (F, f0) => albedoOverLight(brdf(F, f0), Math.acos(0.4), 0.4);
    const [scale, bias] = dfgSplitSum(0.4, 0.4);
    expect(scale + bias).toBeCloseTo(over('schlick', 1), 7);
    expect(scale + bias).toBeCloseTo(over('one'), 7);
    expect(bias).toBeCloseTo(over('schlick', 0), 7);
  });
});

describe('split sum with a fixed node count (what the tables are built with)', () => {
  it('24 Gauss-Legendre nodes per piece: within 2e-5 of the adaptive quadrature (GGX, height-correlated Smith)', () => {
    for (const alpha of [0.01, 0.1, 0.5, 1]) {
      for (const mu of [1e-3, 0.05, 0.5, 1]) {
        const [s, b] = dfgSplitSum(mu, alpha);
        const [s24, b24] = dfgSplitSum(mu, alpha, {}, { nodes: 24 });
        expect(Math.max(Math.abs(s - s24), Math.abs(b - b24))).toBeLessThan(2e-5);
      }
    }
  });
});
