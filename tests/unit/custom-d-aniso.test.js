// The user's anisotropic D (slot DAniso, float customDAniso(vec3 h, vec2 alpha)): its check plan and report
// against independent truths. The GPU's values are stood in for here by float64 functions rounded to float32 (the
// browser test, custom-d-aniso.test.js, runs the same checks on the GPU): the normalisation ∫ D(h)(n·h) dω is 1
// for GGX and Beckmann by Heitz 2014 and 1/π for a D without its π; the weak furnace G1(v) ∫ D ⟨v·h⟩ dω / (n·v) is
// 1 for every v only with the Λ that matches D (Heitz 2014, eq. 24); the quadrature itself against a fine
// midpoint rule in (θ, φ).
import { describe, expect, it } from 'vitest';
import { SLOTS } from '../../src/core/custom/slots.js';
import { ANISOTROPIC_PAIRS, anisotropicNormalisationNodes, checkPlan } from '../../src/core/custom/check-inputs.js';
import { checkReport } from '../../src/core/custom/check-report.js';
import { referenceOptions } from '../../src/core/custom/references.js';
import { ndfBeckmannAniso, ndfGGXAniso, smithG1GGXAniso } from '../../src/math/anisotropic.js';

/** The values a GPU would return for `d(hx, hy, hz, ax, ay)` at every input of the plan: 4 floats per input. */
function valuesOf(plan, d) {
  const out = new Float32Array(plan.inputs.length * 4);
  plan.inputs.forEach((input, i) => (out[i * 4] = d(...input.map(Math.fround))));
  return out;
}
const plan = checkPlan('DAniso');
const report = (d, reference) => checkReport(plan, valuesOf(plan, d), reference);

describe('the anisotropic D slot', () => {
  it('has the signature of issue 28 and compares with the anisotropic GGX and Beckmann of src/math', () => {
    expect(SLOTS.DAniso.signature).toBe('float customDAniso(vec3 h, vec2 alpha)');
    expect(SLOTS.DAniso.call).toBe('customDAniso(m.h, m.alpha)'); // the microfacet input's h and (αx, αy)
    expect(Object.keys(referenceOptions('DAniso'))).toEqual(['ggxAniso', 'beckmannAniso']);
  });

  it('the quadrature: unit h above the horizon; a lobe’s ∫ g (n·h) dω against a 2000 × 4000 midpoint rule', () => {
    for (const pair of ANISOTROPIC_PAIRS)
      for (const { h } of anisotropicNormalisationNodes(pair)) {
        expect(Math.hypot(...h)).toBeCloseTo(1, 12);
        expect(h[2]).toBeGreaterThan(0);
      }
    // a lobe off n, against the midpoint rule in (θ, φ): ∫ g(h) (n·h) dω for g = exp(-|h - c|² / 0.1)
    const c = [0.4, -0.2, Math.sqrt(0.8)];
    const g = (h) => Math.exp(-((h[0] - c[0]) ** 2 + (h[1] - c[1]) ** 2 + (h[2] - c[2]) ** 2) / 0.1);
    const [nt, np] = [2000, 4000];
    let truth = 0;
    for (let i = 0; i < nt; i++) {
      const t = ((i + 0.5) / nt) * (Math.PI / 2);
      for (let k = 0; k < np; k++) {
        const p = ((k + 0.5) / np) * 2 * Math.PI;
        const h = [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
        truth += g(h) * h[2] * Math.sin(t);
      }
    }
    truth *= (Math.PI / 2 / nt) * ((2 * Math.PI) / np);
    const nodes = anisotropicNormalisationNodes([0.5, 0.5]);
    expect(nodes.reduce((s, n) => s + n.weight * g(n.h), 0) / truth).toBeCloseTo(1, 3);
  });

  it('GGX with GGX’s Λ passes both: normalisation within 1e-5, the weak furnace within 2e-3 at every v', () => {
    const r = report(ndfGGXAniso, 'ggxAniso');
    expect(Math.abs(r.normalisation.worst - 1)).toBeLessThan(1e-5);
    expect(Math.abs(r.weakFurnace.worst - 1)).toBeLessThan(2e-3);
    expect(r.weakFurnace.byView).toHaveLength(ANISOTROPIC_PAIRS.length * 10);
    expect(r.reference.pass).toBe(true);
    expect(r.nonFinite.count).toBe(0);
  });

  it('Beckmann with Beckmann’s Λ passes; with GGX’s Λ its weak furnace fails by more than 10 %', () => {
    const right = report(ndfBeckmannAniso, 'beckmannAniso');
    expect(Math.abs(right.normalisation.worst - 1)).toBeLessThan(1e-5);
    expect(Math.abs(right.weakFurnace.worst - 1)).toBeLessThan(2e-3);
    const wrongLambda = report(ndfBeckmannAniso, 'ggxAniso');
    expect(Math.abs(wrongLambda.normalisation.worst - 1)).toBeLessThan(1e-5); // normalised all the same
    expect(Math.abs(wrongLambda.weakFurnace.worst - 1)).toBeGreaterThan(0.1);
    expect(wrongLambda.reference.pass).toBe(false);
  });

  it('a D without its π fails the normalisation (1/π) and the weak furnace; a swapped pair fails the others', () => {
    const noPi = report((...a) => ndfGGXAniso(...a) * Math.PI, 'ggxAniso');
    expect(noPi.normalisation.worst / Math.PI).toBeCloseTo(1, 4);
    expect(Math.abs(noPi.weakFurnace.worst - 1)).toBeGreaterThan(1);
    // αx and αy exchanged: the nodes follow the pair, so a lobe stretched across it (10:1 at (0.05, 0.5)) is read
    // low, and the weak furnace and the reference fail; a lobe of half or twice the pair's widths is still read
    // normalised (the rule does not need the user's D to be the reference)
    const swapped = report((hx, hy, hz, ax, ay) => ndfGGXAniso(hx, hy, hz, ay, ax), 'ggxAniso');
    expect(Math.abs(swapped.weakFurnace.worst - 1)).toBeGreaterThan(0.05);
    expect(swapped.reference.pass).toBe(false);
    for (const k of [0.5, 2]) {
      const scaled = report((hx, hy, hz, ax, ay) => ndfGGXAniso(hx, hy, hz, k * ax, k * ay), 'ggxAniso');
      expect(Math.abs(scaled.normalisation.worst - 1)).toBeLessThan(1e-4);
    }
    // the weak furnace is G1 ∫ D ⟨v·h⟩ / (n·v): at v = n it is the normalisation times G1(n) = 1
    const atN = noPi.weakFurnace.byView.find((b) => b.thetaV === 0);
    expect(smithG1GGXAniso(0, 0, 1, 0.1, 0.1)).toBe(1);
    expect(atN.value).toBeCloseTo(noPi.normalisation.byAlpha[0].integral, 2);
  });
});
