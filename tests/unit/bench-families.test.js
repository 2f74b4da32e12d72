// The bench's families say what each variant is: the reference, an approximation of one model, or another
// model whose distance is a difference. An error is only ever measured between two forms of one model.
import { describe, expect, it } from 'vitest';
import { FAMILIES, measureErrors } from '../../bench/families.js';
import * as M from '../../src/math/index.js';
import { readFileSync } from 'node:fs';
import { measuredLines } from '../../bench/readme-lines.js';
import { MULTIPLE_SCATTERING_FAMILY, WALK_SAMPLES, walkStandardError } from '../../bench/multiple-scattering-family.js';

const KINDS = ['reference', 'approximation', 'difference'];

describe('bench families: errors only between forms of one model', () => {
  for (const family of FAMILIES) {
    const byKey = new Map(family.variants.map((v) => [v.key, v]));
    it(`${family.key}: one reference first; approximations share their target's model, differences do not`, () => {
      expect(family.variants[0].kind).toBe('reference');
      expect(family.variants.filter((v) => v.kind === 'reference')).toHaveLength(1);
      for (const v of family.variants) {
        expect(KINDS, v.key).toContain(v.kind);
        expect(typeof v.model, v.key).toBe('string');
        if (v.kind === 'reference') {
          expect(v.against, v.key).toBeUndefined();
          continue;
        }
        const target = byKey.get(v.against);
        expect(target, `${v.key} is measured against "${v.against}", not a variant of ${family.key}`).toBeDefined();
        // what an error is measured against is an exact form (the reference, or another model's exact form)
        expect(target.kind, `${v.key} against ${target.key}`).not.toBe('approximation');
        if (v.kind === 'approximation') expect(v.model, `${v.key} approximates ${target.key}`).toBe(target.model);
        else {
          expect(target.kind, `${v.key} differs from the reference`).toBe('reference');
          expect(v.model, `${v.key} is another model than ${target.key}`).not.toBe(target.model);
        }
      }
      // every exact form is its own model: two variants of one model cannot both be exact
      const exact = family.variants.filter((v) => v.kind !== 'approximation').map((v) => v.model);
      expect(new Set(exact).size).toBe(exact.length);
    });
  }

  it('measures each variant against its own target: Schlick-GGX against separable Smith (Karis 2013 fits G1)', () => {
    const vis = FAMILIES.find((f) => f.key === 'visibility');
    const errors = Object.fromEntries(measureErrors(vis).map((e) => [e.key, e]));
    let worst = 0;
    for (const [nl, nv, , , a] of vis.inputs) {
      const g = (V) => V(nl, nv, a) * nl * nv;
      worst = Math.max(worst, Math.abs(g(M.visibilitySchlickGGX) - g(M.visibilitySmithGGXSeparable)));
    }
    expect(errors['schlick-ggx'].maxAbs).toBe(worst);
    expect(errors.correlated.maxAbs).toBe(0);
  });

  it('the NDF family scores only Blinn-Phong (Walter’s exponent) as an error against Beckmann', () => {
    const ndf = FAMILIES.find((f) => f.key === 'ndf');
    expect(ndf.variants.filter((v) => v.kind === 'approximation').map((v) => v.key)).toEqual(['blinn-phong']);
    expect(ndf.variants.filter((v) => v.kind === 'difference').map((v) => v.key)).toEqual(['ggx', 'abc', 'sgd']);
  });
});

describe('docs/performance.md: the measured block (bench/readme-lines.js over bench/results/latest.json)', () => {
  const read = (path) => readFileSync(new URL(`../../${path}`, import.meta.url), 'utf8');
  const report = JSON.parse(read('bench/results/latest.json'));
  const doc = read('docs/performance.md');
  it('is what the generator writes from the report', () => {
    expect(doc).toContain(measuredLines(report).join('\n'));
  });
  it('multiple scattering’s errors: uncertain by the walk’s standard error (a 2000-path walk’s ÷ 10 agrees)', () => {
    expect(doc).not.toMatch(/term families are exact/);
    const head = doc.split('\n').find((line) => line.startsWith('Measured '));
    expect(head).toContain(
      'except multiple scattering, scored against a random walk (Heitz et al. 2016), itself uncertain',
    );
    const m = head.match(/(\d+)k paths per \(μ, α\); the walk's largest standard error is ([\d.]+e-\d)/);
    expect(m).not.toBeNull();
    const [paths, quoted] = [Number(m[1]) * 1000, Number(m[2])];
    expect(paths).toBe(WALK_SAMPLES);
    // the same walks at 2000 paths: the standard error falls as 1/√paths
    MULTIPLE_SCATTERING_FAMILY.configure({ quick: true });
    const scaled = walkStandardError() * Math.sqrt(2000 / paths);
    MULTIPLE_SCATTERING_FAMILY.configure({ quick: false });
    expect(Math.abs(scaled / quoted - 1)).toBeLessThan(0.15);
  }, 30_000);
});
