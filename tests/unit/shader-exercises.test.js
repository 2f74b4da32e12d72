// Shader exercises, the pure parts: the format's validation (each bad field named), the input grid, the
// comparison and the feedback, checked against closed forms and against float32 arithmetic done by hand
// (Math.fround after every operation, as a GPU without fused multiply-add computes).
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateExercise } from '../../src/exercises/validate.js';
import {
  axisValues,
  compareValues,
  describePoint,
  domainGrid,
  excess,
  fmtInput,
  fmtShort,
  gradeShader,
  referenceValues,
} from '../../src/exercises/shader-grader.js';
import { GRADED_SLOTS, directionsOf } from '../../src/exercises/shader-slots.js';
import { ndfGGX } from '../../src/math/ndf.js';
import { fresnelDielectric, fresnelSchlick } from '../../src/math/fresnel.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';
import { diffuseFresnelWeighted } from '../../src/math/diffuse.js';
import { parseCustom } from '../../src/core/custom/parse.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { SHADER_SOLUTIONS } from '../browser/shader-solutions.js';

const DIR = join(import.meta.dirname, '../../public/exercises');
const SHADER_IDS = JSON.parse(readFileSync(join(DIR, 'index.json'), 'utf8'))
  .exercises.filter((f) => f.startsWith('shader-'))
  .map((f) => f.replace('.json', ''));
const read = (id) => JSON.parse(readFileSync(join(DIR, `${id}.json`), 'utf8'));
const schemaOf = async () => null;
const validated = async (raw) => validateExercise(raw, { schemaOf });
const errorsOf = async (raw) => (await validated(raw)).errors;
const f = Math.fround;

/** A GPU stand-in: fn(point's float32 arguments) → value(s), packed 4 floats per input as evaluateCustom does. */
const fakeGpu = (fn) => (slot, code, inputs) => {
  const out = new Float32Array(inputs.length * 4);
  inputs.forEach((args, i) => out.set([fn(...args)].flat(), i * 4));
  return out;
};
const parsesOk = () => ({ ok: true, problems: [], params: [] });

/** Textbook GGX in float32: a² / (π (c²(a² − 1) + 1)²): the bracket is 0 at c = 1 once a² < 3e-8. */
const ggxTextbook32 = (nh, alpha) => {
  if (!(nh > 0)) return 0;
  const a2 = f(alpha * alpha);
  const d = f(f(f(nh * nh) * f(a2 - 1)) + 1);
  return f(a2 / f(f(f(Math.PI) * d) * d));
};
/** GGX as the app writes it, in float32: a² / (π (a² c² + (1 − c)(1 + c))²). */
const ggxStable32 = (nh, alpha) => {
  if (!(nh > 0)) return 0;
  const c = Math.min(nh, 1);
  const d = f(f(f(f(alpha * alpha) * c) * c) + f(f(1 - c) * f(1 + c)));
  const t = f(alpha / d);
  return f(f(t * t) / f(Math.PI));
};

describe('shipped shader exercises', () => {
  it('eleven, each valid, one per task of the issues', async () => {
    expect(SHADER_IDS).toHaveLength(11);
    for (const id of SHADER_IDS) expect(await errorsOf(read(id)), id).toEqual([]);
  });

  it('every starter, correct answer and mistake passes custom-core’s static check (parseCustom)', async () => {
    expect(Object.keys(SHADER_SOLUTIONS).sort()).toEqual([...SHADER_IDS].sort());
    for (const id of SHADER_IDS) {
      const { slot, starter } = read(id);
      const codes = [
        starter,
        SHADER_SOLUTIONS[id].correct,
        ...SHADER_SOLUTIONS[id].mistakes.map((m) => m.code ?? starter),
      ];
      for (const code of codes) expect(parseCustom(slot, code).problems, `${id}: ${code}`).toEqual([]);
    }
  });

  it('the slot axes give evaluateCustom the inputs SLOTS describes, one number per input entry', () => {
    for (const [key, slot] of Object.entries(GRADED_SLOTS)) {
      const point = Object.fromEntries(Object.keys(slot.axes).map((a) => [a, 0.5]));
      expect(slot.gpuArgs(point), key).toHaveLength(SLOTS[key].inputs.length);
    }
  });

  it('each grid stays within the render-target limit and names its sources with a year', async () => {
    for (const id of SHADER_IDS) {
      const { exercise } = await validated(read(id));
      const n = domainGrid(exercise.domain, Object.keys(GRADED_SLOTS[exercise.slot].axes)).length;
      expect(n, id).toBeLessThanOrEqual(16384);
      expect(n, id).toBeGreaterThan(50);
      for (const s of exercise.sources) expect(s).toMatch(/\d{4}/);
    }
  });

  it('the numbers the prompts quote, recomputed', () => {
    // GGX: at α = 1e-4, α² − 1 rounds to −1 in float32; D(1) = 1/(π α²) ≈ 3.2e7
    expect(f(f(1e-4 * 1e-4) - 1)).toBe(-1);
    expect(fmtShort(ndfGGX(1, 1e-4))).toBe('3.2e7');
    expect(1 / (Math.PI * 1e-8)).toBeCloseTo(3.18e7, -5);
    // the bug: 1 − c·c in float32 loses up to about 1e-4 of sin²θ near c = 1 (c·c to a multiple of 2^-24 ≈ 6e-8)
    expect(2 ** -24).toBeCloseTo(5.96e-8, 9);
    let worst = 0;
    for (let c = f(0.999); c < 1; c = f(c + 2 ** -24)) {
      const exact = (1 - c) * (1 + c);
      worst = Math.max(worst, Math.abs(f(1 - f(c * c)) - exact) / exact);
      expect(Math.abs(f(f(1 - c) * f(1 + c)) - exact) / exact).toBeLessThan(2 ** -23); // the fix: one rounding
    }
    expect(worst).toBeGreaterThan(5e-5);
    expect(worst).toBeLessThan(1.5e-4);
    // exact Fresnel: η from F0 = ((η − 1)/(η + 1))², the prompt's g-form equals the catalogue's (Fresnel 1823)
    const eta = (1 + Math.sqrt(0.04)) / (1 - Math.sqrt(0.04));
    expect(((eta - 1) / (eta + 1)) ** 2).toBeCloseTo(0.04, 12);
    for (const cos of [1e-4, 0.3, 0.7, 1]) {
      const g = Math.sqrt(eta * eta - 1 + cos * cos);
      const F = 0.5 * ((g - cos) / (g + cos)) ** 2 * (1 + ((cos * (g + cos) - 1) / (cos * (g - cos) + 1)) ** 2);
      expect(F).toBeCloseTo(fresnelDielectric(cos, eta), 12);
    }
  });
});

describe('validation names every bad field', () => {
  const base = () => read('shader-ggx-tiny-alpha');
  const cases = [
    [
      'unknown kind',
      { kind: 'movie' },
      ['kind: unknown kind "movie" (kinds: shader; without "kind", a widget exercise)'],
    ],
    [
      'unknown slot',
      { slot: 'X' },
      ['slot: "X" is not a slot graded against a term (slots: D, V, F, DAniso, VAniso, diffuse)'],
    ],
    ['a widget field', { grader: 'smith-g1' }, [/^grader: unknown field \(fields: id, kind, chapter/]],
    ['no sources', { sources: undefined }, [/^sources: missing/]],
    ['a source without a year', { sources: ['Walter et al.'] }, ['sources: "Walter et al." names no author and year']],
    ['no starter', { starter: 3 }, ['starter: missing (the GLSL code the editor starts with)']],
    ['a long starter', { starter: 'x'.repeat(8001) }, ['starter: 8001 characters; at most 8000']],
    ['tolerance as a number', { tolerance: 0.01 }, [/^tolerance: missing \(an object/]],
    ['tolerance out of range', { tolerance: { rel: -1, abs: 0 } }, ['tolerance.rel: -1 is not a number within 0…1']],
    ['tolerance both 0', { tolerance: { rel: 0, abs: 0 } }, ['tolerance: rel and abs cannot both be 0']],
    ['term of another family', { reference: { term: 'schlick' } }, [/^reference.term: "schlick" is not a ndf term/]],
    [
      'a term reading what the slot lacks',
      { slot: 'V', reference: { term: 'cookTorrance' }, domain: read('shader-smith-g1').domain, plot: undefined },
      [
        'reference.term: "cookTorrance" reads nh, which V\'s function does not get',
        'reference.term: "cookTorrance" reads lh, which V\'s function does not get',
      ],
    ],
    [
      'a parameter neither an axis nor fixed',
      { ...read('shader-lambert-tradeoff'), reference: { term: 'fresnelWeighted' } },
      ['reference.params.f0: missing ("fresnelWeighted" reads it and the slot does not give it)'],
    ],
    [
      'a fixed parameter out of range',
      { ...read('shader-lambert-tradeoff'), reference: { term: 'fresnelWeighted', params: { f0: 2 } } },
      ['reference.params.f0: 2 is not a number within 0…1'],
    ],
    [
      'an inherited name as a parameter',
      JSON.parse('{ "reference": { "term": "ggx", "params": { "__proto__": 1 } } }'),
      ['reference.params.__proto__: "ggx" has no parameter __proto__'],
    ],
    ['a missing axis', { domain: { nh: base().domain.nh } }, ['domain.alpha: missing (roughness α)']],
    ['an unknown axis', { domain: { ...base().domain, nl: { stress: [1] } } }, [/^domain.nl: not an axis of slot "D"/]],
    [
      'a bad range',
      { domain: { ...base().domain, nh: { range: [1, 0], steps: 3 } } },
      ['domain.nh.range: [1,0] is not [min, max] with min < max within -1…1.001'],
    ],
    [
      'a bad steps',
      { domain: { ...base().domain, nh: { range: [0, 1], steps: 1.5 } } },
      ['domain.nh.steps: 1.5 is not a whole number within 2…101'],
    ],
    [
      'a stress value past the limits',
      { domain: { ...base().domain, nh: { stress: [3] } } },
      ['domain.nh.stress: 3 is not a number within -1…1.001'],
    ],
    [
      'too many inputs',
      {
        ...read('shader-smith-g1'),
        domain: Object.fromEntries(['nl', 'nv', 'alpha'].map((a) => [a, { range: [0.01, 1], steps: 30 }])),
      },
      ['domain: 27,000 inputs; the grid holds at most 16384'],
    ],
    [
      'a plot on no axis',
      { plot: { x: 'q', at: { alpha: 0.5 } } },
      [/^plot.x: "q" is not an axis/, 'plot.at.nh: undefined is not a number within -1…1.001'],
    ],
    [
      'a plot without the other axes',
      { plot: { x: 'nh', at: {} } },
      ['plot.at.alpha: undefined is not a number within 0…10'],
    ],
  ];
  it.each(cases)('%s', async (_, patch, expected) => {
    const errors = await errorsOf({ ...base(), ...patch });
    expect(errors).toHaveLength(expected.length);
    expected.forEach((e, i) => (typeof e === 'string' ? expect(errors[i]).toBe(e) : expect(errors[i]).toMatch(e)));
  });
});

describe('the grid', () => {
  it('an axis is its evenly spaced range and its stress values, sorted, without repeats', () => {
    expect(axisValues({ range: [0, 1], steps: 5, stress: [0.5, 1e-7, -0.5] })).toEqual([
      -0.5, 0, 1e-7, 0.25, 0.5, 0.75, 1,
    ]);
    expect(axisValues({ stress: [0.3, 0.1] })).toEqual([0.1, 0.3]);
  });

  it('the grid is the cartesian product: |nh| × |alpha| points, each pair once', () => {
    const grid = domainGrid({ nh: { range: [0, 1], steps: 3 }, alpha: { stress: [0.1, 0.5] } }, ['nh', 'alpha']);
    expect(grid).toEqual([
      { nh: 0, alpha: 0.1 },
      { nh: 0, alpha: 0.5 },
      { nh: 0.5, alpha: 0.1 },
      { nh: 0.5, alpha: 0.5 },
      { nh: 1, alpha: 0.1 },
      { nh: 1, alpha: 0.5 },
    ]);
  });

  it('the reference is the catalogue term at the float32-rounded inputs (GGX, Schlick, correlated Smith)', async () => {
    const ggx = (await validated(read('shader-ggx-tiny-alpha'))).exercise;
    const p = { nh: 0.999999, alpha: 0.3 };
    expect(referenceValues(ggx, [p])[0]).toBe(ndfGGX(f(0.999999), f(0.3)));
    expect(referenceValues(ggx, [p])[0]).not.toBe(ndfGGX(0.999999, 0.3));
    const schlick = (await validated(read('shader-schlick'))).exercise;
    expect(referenceValues(schlick, [{ f0: 0.04, lh: 1.000001 }])[0]).toBe(f(0.04)); // clamped: F(1) = F0
    expect(referenceValues(schlick, [{ f0: 0.04, lh: 0.5 }])[0]).toBe(fresnelSchlick(f(0.04), 0.5));
    const v = (await validated(read('shader-smith-correlated'))).exercise;
    expect(referenceValues(v, [{ nl: 0.1, nv: 0.7, alpha: 0.5 }])[0]).toBe(
      visibilitySmithGGXCorrelated(f(0.1), f(0.7), 0.5),
    );
  });

  it('the diffuse slot gets unit vectors with the asked cosines; the reference reads the rounded ones', async () => {
    const { l, v } = directionsOf(0.6, 0.8, -1);
    expect(Math.hypot(...l)).toBeCloseTo(1, 7);
    expect(l).toEqual([f(0.8), 0, f(0.6)]);
    expect(v).toEqual([f(-0.6), 0, f(0.8)]);
    const ex = (await validated(read('shader-lambert-tradeoff'))).exercise;
    expect(referenceValues(ex, [{ cdiff: 1, nl: 0.6, nv: 0.8, cosPhi: -1, alpha: 0.5 }])[0]).toBe(
      diffuseFresnelWeighted(f(0.6), f(0.8), 0.04, 1),
    );
  });

  it('the exact dielectric gets the η whose F0 the slot gives: F(1) = F0', async () => {
    const ex = (await validated(read('shader-fresnel-exact'))).exercise;
    expect(referenceValues(ex, [{ f0: 0.04, lh: 1 }])[0]).toBeCloseTo(f(0.04), 9);
  });
});

describe('the comparison', () => {
  const tol = { rel: 1e-3, abs: 1e-5 };
  it('excess is the error in tolerances; NaN and Inf never pass against a finite reference', () => {
    expect(excess(1.001, 1, tol)).toBeCloseTo(0.001 / (1e-5 + 1e-3), 9);
    expect(excess(NaN, 0, tol)).toBe(Infinity);
    expect(excess(Infinity, 3.2e7, tol)).toBe(Infinity);
  });

  it('counts passing inputs, NaN/Inf, negatives, and picks the input of largest excess', () => {
    const gpu = new Float32Array([1, 0, 0, 0, NaN, 0, 0, 0, -0.5, 0, 0, 0, 2.002, 0, 0, 0]);
    const r = compareValues(gpu, [1, 1, 0, 2], 1, tol);
    expect(r).toMatchObject({ count: 4, passing: 2, nonFinite: 1, negative: 1 });
    expect(r.worst).toMatchObject({ index: 1, reference: 1 });
    expect(r.worst.value).toBeNaN();
  });

  it('finds a common factor: π everywhere is one missing π', () => {
    const refs = [0.1, 0.2, 0.3, 0.05];
    const gpu = new Float32Array(refs.flatMap((x) => [x * Math.PI, 0, 0, 0]));
    expect(compareValues(gpu, refs, 1, tol).ratio).toBeCloseTo(Math.PI, 5);
  });

  it('formats numbers as the page does, shortened: 3.2e7, 1e-4, Inf, and inputs to their float32 digits', () => {
    expect([3.18e7, 1e-4, Infinity, NaN, 0.318, -2].map((x) => fmtShort(x))).toEqual([
      '3.2e7',
      '1e-4',
      'Inf',
      'NaN',
      '0.32',
      '−2',
    ]);
    expect([0.999999, 1e-4, 1, 1.000001, -0.5].map(fmtInput)).toEqual(['0.999999', '1e-4', '1', '1.000001', '−0.5']);
    expect(describePoint('D', { nh: 1, alpha: 1e-4 })).toBe('n·h = 1, α = 1e-4');
  });
});

describe('grading with float32 arithmetic by hand in place of the GPU', () => {
  it('textbook GGX: "at n·h = 1, α = 1e-4 your D is Inf; the reference is 3.2e7" (1/(π α²))', async () => {
    const ex = (await validated(read('shader-ggx-tiny-alpha'))).exercise;
    const r = gradeShader(ex, 'code', { parse: parsesOk, evaluate: fakeGpu(ggxTextbook32) });
    expect(r.passed).toBe(false);
    expect(r.summary).toBe('At n·h = 1, α = 1e-4 your D is Inf; the reference is 3.2e7.');
    expect(r.score).toBeGreaterThan(0.5);
    expect(r.score).toBeLessThan(1);
    expect(r.details[0]).toMatch(
      /^\d+ of 216 inputs match within \|yours − reference\| ≤ 1e-5 \+ 0\.001·\|reference\|/,
    );
  });

  it('GGX with (1 − c)(1 + c) in float32 passes at every input, score 1', async () => {
    for (const id of ['shader-ggx-tiny-alpha', 'shader-fix-cancellation']) {
      const ex = (await validated(read(id))).exercise;
      const r = gradeShader(ex, 'code', { parse: parsesOk, evaluate: fakeGpu(ggxStable32) });
      expect(r, id).toMatchObject({ passed: true, score: 1 });
      expect(r.summary).toMatch(/^Right: your D matches GGX at all \d+ inputs/);
    }
  });

  it('the bug 1 − c·c in float32 fails near c = 1, named there', async () => {
    const ex = (await validated(read('shader-fix-cancellation'))).exercise;
    const buggy = (nh, alpha) => {
      if (!(nh > 0)) return 0;
      const a2 = f(alpha * alpha);
      const c2 = f(nh * nh);
      const d = f(f(a2 * c2) + f(1 - c2));
      return f(a2 / f(f(f(3.14159265) * d) * d));
    };
    const r = gradeShader(ex, 'code', { parse: parsesOk, evaluate: fakeGpu(buggy) });
    expect(r.passed).toBe(false);
    // worst near the peak of a sharp lobe, where sin²θ dominates α²c² (1 − c from 2e-4 to 5e-5)
    expect(r.summary).toMatch(
      /^At n·h = 0\.999(8|83|9|95), α = (0\.001|0\.003|0\.01) your D is [\d.]+; the reference is [\d.]+\.$/,
    );
    const [, yours, ref] = r.summary.match(/your D is ([\d.]+); the reference is ([\d.]+)/);
    expect(yours).not.toBe(ref); // shown with the digits that tell them apart
  });

  it('Lambert without π in the trade-off: the factor π is named', async () => {
    const ex = (await validated(read('shader-lambert-tradeoff'))).exercise;
    const weighted = (c, lx, ly, lz, vx, vy, vz) =>
      lz > 0 && vz > 0 ? (1 - fresnelSchlick(0.04, lz)) * (1 - fresnelSchlick(0.04, vz)) * c : 0;
    const r = gradeShader(ex, 'code', {
      parse: parsesOk,
      evaluate: fakeGpu((...a) => [a, a, a].map(() => weighted(...a))),
    });
    expect(r.passed).toBe(false);
    expect(r.details).toContain(
      'Wherever both are clearly nonzero, your diffuse BRDF is 3.1× the reference. Is a factor of π missing or extra?',
    );
  });

  it('static-check problems and compile errors come back at the student’s lines, score 0, no GPU run', async () => {
    const ex = (await validated(read('shader-schlick'))).exercise;
    let ran = false;
    const evaluate = () => (
      (ran = true),
      { errors: [{ line: 4, message: "'pow' : no matching overloaded function" }] }
    );
    const loop = { ok: false, problems: [{ line: 2, message: 'a while loop is not allowed' }] };
    const r1 = gradeShader(ex, 'code', { parse: () => loop, evaluate });
    expect(r1).toMatchObject({ passed: false, score: 0, details: ['Line 2: a while loop is not allowed'] });
    expect(ran).toBe(false);
    const r2 = gradeShader(ex, 'code', { parse: parsesOk, evaluate });
    expect(r2.summary).toBe('Your code does not compile:');
    expect(r2.problems).toEqual([{ line: 4, message: "'pow' : no matching overloaded function" }]);
  });

  it('a plot gets the student’s curve and the reference along its x axis', async () => {
    const ex = (await validated(read('shader-ggx-tiny-alpha'))).exercise;
    const { curve } = gradeShader(ex, 'code', { parse: parsesOk, evaluate: fakeGpu(ggxStable32) });
    expect(curve.xLabel).toBe('n·h');
    const i = curve.x.indexOf(1);
    expect(curve.reference[i]).toBeCloseTo(1 / (Math.PI * f(0.1) ** 2), 3);
    expect(curve.yours[i] / curve.reference[i]).toBeCloseTo(1, 5);
  });
});
