// The live checks' arithmetic (src/core/custom/check-inputs.js, check-report.js), fed float32 values computed here in
// place of the GPU's: the quadratures against closed forms (∫ D (n·m) dω = 1 for a normalised D, the albedo of
// Lambert c/π is c) and the float64 albedo of src/math/integrate.js, and each report against counts made by hand.
import { describe, expect, it } from 'vitest';
import {
  CHECK_ALPHAS,
  NORMALISATION_ALPHAS,
  checkPlan,
  furnaceNodes,
  normalisationNodes,
} from '../../src/core/custom/check-inputs.js';
import { checkReport } from '../../src/core/custom/check-report.js';
import { referenceFunction, referenceOptions } from '../../src/core/custom/references.js';
import { GRIDS } from '../../src/core/gpu/parity-cases.js';
import { ndfBeckmann, ndfGGX } from '../../src/math/ndf.js';
import { albedoGGX } from '../../src/math/integrate.js';
import { microfacetBRDF } from '../../src/math/brdf.js';

/** What the GPU would return: f at each input of the plan, as float32, 4 floats per input. */
function simulate(plan, f) {
  const out = new Float32Array(plan.inputs.length * 4);
  plan.inputs.forEach((input, i) => [].concat(f(input.map(Math.fround))).forEach((x, o) => (out[i * 4 + o] = x)));
  return out;
}
const integral = (nodes, D, alpha, round = (x) => x) => nodes.reduce((s, n) => s + n.weight * D(round(n.nh), alpha), 0);

describe('D normalisation ∫ D(m)(n·m) dω (closed form: 1 for every α)', () => {
  it('the rule converges to 1e-8 for GGX and Beckmann in float64, α from 1e-4 to 1', () => {
    for (const alpha of [1e-4, 1e-3, ...NORMALISATION_ALPHAS])
      for (const D of [ndfGGX, ndfBeckmann])
        expect(Math.abs(integral(normalisationNodes(alpha), D, alpha) - 1), `${D.name} ${alpha}`).toBeLessThan(1e-8);
  });
  it('through a float32 n·h: within 5e-5 from α = 0.01 up, but off by more than 1e-3 at α = 1e-3', () => {
    for (const alpha of NORMALISATION_ALPHAS)
      expect(Math.abs(integral(normalisationNodes(alpha), ndfGGX, alpha, Math.fround) - 1)).toBeLessThan(5e-5);
    expect(Math.abs(integral(normalisationNodes(1e-3), ndfGGX, 1e-3, Math.fround) - 1)).toBeGreaterThan(1e-3);
  });
  it('reads 1 ± 1e-4 for GGX values, π for GGX without its 1/π, at every measured α', () => {
    const plan = checkPlan('D');
    const good = checkReport(
      plan,
      simulate(plan, ([nh, a]) => ndfGGX(nh, a)),
    );
    expect(Math.abs(good.normalisation.worst - 1)).toBeLessThan(1e-4);
    expect(good.normalisation.byAlpha.map((r) => r.alpha)).toEqual(NORMALISATION_ALPHAS);
    const noPi = checkReport(
      plan,
      simulate(plan, ([nh, a]) => ndfGGX(nh, a) * Math.PI),
    );
    expect(Math.abs(noPi.normalisation.worst - Math.PI)).toBeLessThan(4e-4);
    for (const r of noPi.normalisation.byAlpha) expect(r.integral / Math.PI).toBeCloseTo(1, 4);
  });
});

describe('nonFinite and the reference (counted by hand over the stress grid)', () => {
  it('a D that is Inf at n·h = 1 names that input first; one bad input per α; against GGX it is the worst', () => {
    const plan = checkPlan('D');
    const values = simulate(plan, ([nh, a]) => (nh === 1 ? Infinity : ndfGGX(nh, a)));
    const report = checkReport(plan, values);
    expect(report.nonFinite.count).toBe(CHECK_ALPHAS.length); // n·h = 1 once per α (1 + 1e-6 is not 1 in float32)
    expect(report.nonFinite.first).toEqual({
      inputs: { nh: 1, alpha: Math.fround(1e-4) },
      value: Infinity,
      text: 'Infinity',
    });
    expect(report.reference.worst.inputs.nh).toBe(1);
    expect(report.reference.worst.value).toBe(Infinity);
    expect(report.reference.worst.reference).toBeCloseTo(1 / (Math.PI * Math.fround(1e-4) ** 2), -1);
  });
  it('the catalogue GGX rounded to float32 passes against itself; without π its max relative error is π − 1', () => {
    const plan = checkPlan('D');
    const ggx = referenceFunction('D', 'ggx');
    expect(
      checkReport(
        plan,
        simulate(plan, (x) => ggx(x)),
      ).reference,
    ).toMatchObject({ pass: true, failures: 0 });
    const noPi = checkReport(
      plan,
      simulate(plan, (x) => ggx(x)[0] * Math.PI),
    ).reference;
    expect(noPi.maxRel).toBeCloseTo(Math.PI - 1, 5);
    expect(noPi.pass).toBe(false);
  });
  it('negative values are counted apart from NaN/Inf', () => {
    const plan = checkPlan('F');
    const report = checkReport(
      plan,
      simulate(plan, ([r, g, b]) => [r - 0.5, g, b]),
    );
    const expected = GRIDS.f0.filter((f0) => Math.fround(f0) < 0.5).length * GRIDS.cos.length;
    expect(report.nonFinite).toMatchObject({ count: 0, negative: expected });
  });
});

describe('V: G = V (n·l)(n·v) within [0, 1]', () => {
  it('V = 2/((n·l)(n·v)) puts G = 2 outside at every input above the horizon; V = 1 keeps G inside', () => {
    const plan = checkPlan('V');
    const bad = checkReport(
      plan,
      simulate(plan, ([nl, nv]) => (nl > 0 && nv > 0 ? 2 / (nl * nv) : 0)),
    );
    const above = GRIDS.cosCoarse.filter((c) => c > 0).length;
    expect(bad.gRange.outside).toBe(above * above * CHECK_ALPHAS.length);
    expect(bad.gRange.max).toBeCloseTo(2, 5);
    const implicit = checkReport(
      plan,
      simulate(plan, ([nl, nv]) => (nl > 0 && nv > 0 ? 1 : 0)),
      'implicit',
    );
    expect(implicit.gRange.outside).toBe(0);
    expect(implicit.reference.pass).toBe(true);
  });
});

describe('a whole BRDF: white furnace and reciprocity', () => {
  it('Lambert with albedo 0.7 reads furnace 0.7 (closed form) and reciprocity 0', () => {
    const plan = checkPlan('brdf');
    const report = checkReport(
      plan,
      simulate(plan, ([, , lz, , , vz]) => (lz > 0 && vz > 0 ? 0.7 / Math.PI : 0)),
    );
    expect(Math.abs(report.furnace.max - 0.7)).toBeLessThan(1e-6);
    expect(report.reciprocity).toEqual({ maxRel: 0, first: null });
  });
  it('the GGX BRDF (F = 1) reads the float64 albedo of src/math/integrate.js: 1e-4 at α = 0.5 up to θv = 80°', () => {
    const params = { F: 'one', D: 'ggx', V: 'smithGGXCorrelated', alpha: 0.5, f0: 1 };
    const error = (deg) => {
      const nodes = furnaceNodes((deg * Math.PI) / 180);
      const sum = nodes.reduce((s, n) => s + n.weight * microfacetBRDF(n.l, n.v, params), 0);
      return Math.abs(sum - albedoGGX(Math.cos((deg * Math.PI) / 180), 0.5));
    };
    for (const deg of [0, 30, 60, 80]) expect(error(deg), `θv ${deg}°`).toBeLessThan(1e-4);
    expect(error(89)).toBeLessThan(3e-3); // a lobe at the horizon, between the rule's azimuths (FURNACE_RULE)
  });
  it('a BRDF that is not reciprocal is caught, with the pair', () => {
    const plan = checkPlan('brdf');
    const report = checkReport(
      plan,
      simulate(plan, ([, , lz, , , vz]) => (lz > 0 && vz > 0 ? lz / Math.PI : 0)),
    );
    expect(report.reciprocity.maxRel).toBeGreaterThan(0.5);
    expect(report.reciprocity.first.values[0]).not.toBe(report.reciprocity.first.values[1]);
  });
});

describe('references', () => {
  it('offers catalogue terms the slot’s arguments determine, by their catalogue labels', () => {
    expect(referenceOptions('D')).toEqual({ ggx: 'GGX', beckmann: 'Beckmann', blinnPhong: 'Blinn–Phong' });
    expect(Object.keys(referenceOptions('V'))).not.toContain('cookTorrance'); // it needs n·h and v·h
    expect(Object.keys(referenceOptions('F'))).toEqual(['schlick', 'one', 'dielectric']);
  });
  it('the exact dielectric from F0 gives back F0 at normal incidence (F0 = ((η − 1)/(η + 1))²)', () => {
    const [r, g, b] = referenceFunction('F', 'dielectric')([0.04, 0.5, 1, 1]);
    expect(r).toBeCloseTo(Math.fround(0.04), 7);
    expect(g).toBeCloseTo(0.5, 6);
    expect(b).toBe(1);
  });
});
