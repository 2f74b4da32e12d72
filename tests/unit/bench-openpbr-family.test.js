// The bench's OpenPBR family (bench/openpbr-family.js): its errors are those of a direct computation, each stack's
// albedo by another quadrature (tests/support/openpbr-albedo.js, per layer over its own variable) against the same
// seeded walks through the layers; and each stack is the material with the layers above it at weight 0, which the
// GLSL switches compile out.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { measureErrors } from '../../bench/families.js';
import { CASES, FURNACE_SAMPLES, MUS, OPENPBR_FAMILY, STACKS, walkSeed } from '../../bench/openpbr-family.js';
import { layeredWalkAlbedo } from '../../src/math/openpbr-walk.js';
import { openPbrAlbedo } from '../support/openpbr-albedo.js';

const QUICK_PATHS = 2000; // configure({ quick: true }): the quick walk, beside the full run's quadrature
// the family's quadrature (the lab's furnace at 16384 samples per lobe) is within 1.1e-3 of the Gauss rule's
const QUADRATURE = 1.5e-3;

describe('the OpenPBR layers family', () => {
  OPENPBR_FAMILY.configure({ quick: true, furnaceSamples: FURNACE_SAMPLES });
  const errors = Object.fromEntries(measureErrors(OPENPBR_FAMILY).map((e) => [e.key, e]));
  const walks = CASES.map((c, i) => MUS.map((mu, j) => layeredWalkAlbedo(mu, c.stack, QUICK_PATHS, walkSeed(i, j))));

  for (const stack of STACKS) {
    it(`${stack.label}: its albedos, max and RMS error against the walk as computed directly (Gauss rule)`, () => {
      const variant = OPENPBR_FAMILY.variants.find((v) => v.key === stack.key);
      let [max, sq, n] = [0, 0, 0];
      CASES.forEach((c, i) =>
        MUS.forEach((mu, j) => {
          const albedo = openPbrAlbedo({ ...c.material, ...stack.off }, mu, 24).total;
          albedo.forEach((a, ch) => {
            expect(Math.abs(variant.js(mu, i, ch) - a), `${c.label}, μ = ${mu}`).toBeLessThan(QUADRATURE);
            const e = a - walks[i][j].albedo[ch];
            [max, sq, n] = [Math.max(max, Math.abs(e)), sq + e * e, n + 1];
          });
        }),
      );
      expect(Math.abs(errors[stack.key].maxAbs - max)).toBeLessThan(QUADRATURE);
      expect(Math.abs(errors[stack.key].rms - Math.sqrt(sq / n))).toBeLessThan(QUADRATURE);
    });
  }

  it('each layer changes the figures where it is weighted: the coat’s stack is nearer the walk than the talk’s', () => {
    // the coated cases are missed by the stacks without a coat; the fuzz (weight 0 in every case) adds nothing
    expect(errors.base.maxAbs).toBeGreaterThan(errors.talk.maxAbs);
    expect(errors.talk.rms).toBeGreaterThan(errors.coat.rms + 0.01);
    expect(errors.fuzz).toEqual({ ...errors.coat, key: 'fuzz' });
  });

  it('the GLSL switches each variant compiles with are the ones openpbr.glsl reads', () => {
    const glsl = readFileSync(new URL('../../shaders/openpbr.glsl', import.meta.url), 'utf8');
    const used = new Set(OPENPBR_FAMILY.variants.flatMap((v) => Object.keys(v.defines ?? {})));
    expect([...used].sort()).toEqual(['OPENPBR_NO_COAT', 'OPENPBR_NO_FUZZ', 'OPENPBR_NO_SPECULAR']);
    for (const name of used) expect(glsl).toMatch(new RegExp(`#ifn?def ${name}\\b`));
    // a stack leaves out what its switches compile out: its weights at 0
    const weight = {
      OPENPBR_NO_SPECULAR: 'specular_weight',
      OPENPBR_NO_COAT: 'coat_weight',
      OPENPBR_NO_FUZZ: 'fuzz_weight',
    };
    for (const v of OPENPBR_FAMILY.variants.filter((w) => w.defines)) {
      const stack = STACKS.find((s) => s.key === v.key);
      expect(Object.keys(stack.off).sort()).toEqual(
        Object.keys(v.defines)
          .map((d) => weight[d])
          .sort(),
      );
    }
  });
});
