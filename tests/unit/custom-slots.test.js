// The slots of issue 13 (src/core/custom/slots.js) against the signatures the issue fixes, word for word, and the
// catalogue terms they are compared with.
import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../src/math/catalogue/microfacet-input.js';
import { SLOTS, slotOf } from '../../src/core/custom/slots.js';
import { CATALOGUE } from '../../src/math/catalogue/index.js';
import { smithG1GGX } from '../../src/math/visibility.js';

const ISSUE_13 = {
  D: 'float customD(float nh, float alpha)',
  V: 'float customV(float nl, float nv, float alpha)',
  F: 'vec3 customF(vec3 f0, float lh)',
  diffuse: 'vec3 customDiffuse(vec3 cdiff, vec3 l, vec3 v, float alpha)',
  brdf: 'vec3 customBRDF(vec3 l, vec3 v)',
};

describe('SLOTS', () => {
  it.each(Object.entries(ISSUE_13))('%s has the signature of issue 13, and its args say the same', (key, sig) => {
    const slot = slotOf(key);
    expect(slot.signature).toBe(sig);
    expect(`${slot.returns} ${slot.fn}(${slot.args.map((a) => `${a.type} ${a.name}`).join(', ')})`).toBe(sig);
    // D and V: the dispatch passes the user's function the microfacet input's fields (m.nh, m.alpha.x, …)
    const passed = (name) => (slot.family === 'ndf' || slot.family === 'visibility' ? FIELDS[name].glsl : name);
    expect(slot.call).toBe(`${slot.fn}(${slot.args.map((a) => passed(a.name)).join(', ')})`);
    expect(slot.outputs).toBe(slot.returns === 'vec3' ? 3 : 1);
    expect(slot.inputs.length).toBeLessThanOrEqual(8); // what one texel pair carries
  });
  it('compares each with a term of the catalogue', () => {
    const anisotropic = ['DAniso', 'VAniso'];
    for (const slot of Object.values(SLOTS).filter((s) => !anisotropic.includes(s.key)))
      expect(CATALOGUE[slot.family ?? 'diffuse'].terms).toHaveProperty(slot.reference);
    // issue 28's anisotropic D, beside them: compared with src/math/anisotropic.js (custom-d-aniso.test.js); its V,
    // written only in the shader exercises, with the catalogue's anisotropic height-correlated Smith
    expect(Object.keys(SLOTS).filter((k) => !anisotropic.includes(k))).toEqual(Object.keys(ISSUE_13));
    expect(CATALOGUE.visibility.terms).toHaveProperty(SLOTS.VAniso.reference);
    expect(() => slotOf('toString')).toThrow(/no slot/);
  });
  it('the V starter names its root r(x) = x (1 + 2Λ(x)), not Λ: Heitz 2014’s Λ in closed form, G1 = 1/(1 + Λ)', () => {
    const comment = SLOTS.V.starter
      .split('\n')
      .filter((line) => line.startsWith('//'))
      .join(' ');
    expect(comment).toContain('r(x) = sqrt(x² + α² (1 - x²)) = x (1 + 2Λ(x))');
    expect(comment).not.toMatch(/Λ[xlv]\b|Λx =/);
    for (const alpha of [0.1, 0.5, 1])
      for (const x of [0.05, 0.3, 0.7, 1]) {
        const lambda = (-1 + Math.sqrt(1 + (alpha * alpha * (1 - x * x)) / (x * x))) / 2; // Heitz 2014, GGX
        expect(Math.sqrt(x * x + alpha * alpha * (1 - x * x))).toBeCloseTo(x * (1 + 2 * lambda), 12);
        expect(smithG1GGX(x, alpha)).toBeCloseTo(1 / (1 + lambda), 12);
      }
  });
});
