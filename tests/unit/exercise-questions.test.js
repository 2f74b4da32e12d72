// The exercises' questions and attempts: Which NDF draws its hidden highlight in D (1/sr) on the NDF explorer's log
// axes (checked against the NDFs of src/math at the matched width), from a seed a link keeps; its Right feedback
// says the profiles agree in per cent, not "within a factor 1"; an answer checked twice is one attempt.
import { describe, expect, it } from 'vitest';
import { hiddenNdfPlot } from '../../src/exercises/previews.js';
import { MAX_SEED, drawsHidden, hiddenFor, readSeed } from '../../src/exercises/question-seed.js';
import { GRADERS, NDF_NAMES } from '../../src/exercises/graders.js';
import { createProgress } from '../../src/exercises/progress.js';
import { NDF_TERMS } from '../../src/math/brdf.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';
import { DEG } from '../../src/math/angles.js';

const NDF = GRADERS['ndf-profile'];
const PARAMS = { hidden: 'random', hwhm: 10, floor: 0.01, abcA2: 2.5, sgdP: 0.64, lightTheta: 30 };

describe('Which NDF: the picture', () => {
  it('plots D(θh) in 1/sr from 1e-7 of the highest peak to twice it, over 0–90°, as the explorer’s log plot', () => {
    const p = matchNdfWidths(10, { abcA2: 2.5, sgdP: 0.64 });
    const D = (kind, deg) => NDF_TERMS[kind](Math.cos(deg * DEG), p[kind]);
    const peak = Math.max(...Object.keys(NDF_NAMES).map((k) => D(k, 0)));
    for (const hidden of Object.keys(NDF_NAMES)) {
      const spec = hiddenNdfPlot(PARAMS, hidden);
      expect(spec.yLabel).toBe('D (1/sr)');
      expect(spec.x).toEqual({ min: 0, max: 90 });
      expect(spec.y.log).toBe(true);
      expect(spec.y.min / (peak * 1e-7)).toBeCloseTo(1, 12);
      expect(spec.y.max / (peak * 2)).toBeCloseTo(1, 12);
      const [angles, values] = spec.data;
      for (const deg of [0, 2.5, 10, 20]) {
        const i = angles.indexOf(deg);
        expect(values[i] / D(hidden, deg), `${hidden} at ${deg}°`).toBeCloseTo(1, 12);
      }
    }
  });
});

describe('Which NDF: the question number', () => {
  it('reads a whole seed 1…9999 from the address, and draws one (saying why) for a bad one', () => {
    expect(readSeed('42')).toEqual({ seed: 42, problem: null });
    for (const bad of ['0', '1.5', 'x', '', String(MAX_SEED + 1)]) {
      const r = readSeed(bad, () => 0.5);
      expect(r.seed, bad).toBe(5000);
      expect(r.problem, bad).toBe(`seed=${bad} is not a whole number from 1 to 9999: question 5000 is shown.`);
    }
    expect(readSeed(null, () => 0)).toEqual({ seed: 1, problem: null });
  });

  it('the same seed, the same hidden NDF; seeds 1–100 draw each of the five; a named NDF is no draw', () => {
    expect(drawsHidden(NDF, PARAMS)).toBe(true);
    expect(drawsHidden(NDF, { ...PARAMS, hidden: 'ggx' })).toBe(false);
    const drawn = Array.from({ length: 100 }, (_, i) => hiddenFor(NDF, PARAMS, i + 1));
    expect(Array.from({ length: 100 }, (_, i) => hiddenFor(NDF, PARAMS, i + 1))).toEqual(drawn);
    expect(new Set(drawn)).toEqual(new Set(Object.keys(NDF_NAMES)));
  });
});

describe('Which NDF: the feedback', () => {
  it('the right pick says the profiles are the same, a near one by how many per cent, never "a factor 1"', () => {
    const right = NDF.grade({ answer: 'ggx', params: PARAMS, tolerance: 1.2, hidden: 'ggx' });
    expect(right.ok).toBe(true);
    expect(right.summary).toBe(
      'Right: GGX made it: its profile is the highlight’s (profiles within 20% of each other wherever the ' +
        'highlight is above 1% of its peak count).',
    );
    const wrong = NDF.grade({ answer: 'beckmann', params: PARAMS, tolerance: 1.2, hidden: 'ggx' });
    expect(wrong.ok).toBe(false);
    expect(wrong.summary).not.toMatch(/factor 1\b/);
  });
});

describe('attempts', () => {
  it('the same answer checked again (Enter, then Check) is one attempt; a new answer is another', () => {
    const store = new Map();
    const storage = {
      getItem: (k) => store.get(k) ?? null,
      setItem: (k, v) => store.set(k, v),
      removeItem: store.delete,
    };
    const p = createProgress(storage);
    expect(p.record('a', false, '["5",null]')).toBe(true);
    expect(p.record('a', false, '["5",null]')).toBe(false);
    expect(p.of('a')).toEqual({ solved: false, attempts: 1 });
    expect(p.record('a', true, '["14.5",null]')).toBe(true);
    expect(p.of('a')).toEqual({ solved: true, attempts: 2 });
  });
});
