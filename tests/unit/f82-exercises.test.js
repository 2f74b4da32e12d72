// The F82-tint exercises: the grader against the closed form of the gap, b μ(1 − μ)⁶ (the specification's b from
// F0 and the tint), its hints for the two likely slips, and the shipped question solvable from what it shows.
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { GRADERS } from '../../src/exercises/graders.js';
import { f82SchlickGap } from '../../src/exercises/graders/f82-schlick-gap.js';
import { fresnelConductor } from '../../src/math/fresnel.js';
import { measuredRgbNk } from '../../src/math/optical-constants.js';

const grader = GRADERS['f82-schlick-gap'];
const exercise = JSON.parse(
  readFileSync(join(import.meta.dirname, '../../public/exercises/f82-grazing-aluminium.json'), 'utf8'),
);
const schlick = (f0, mu) => f0 + (1 - f0) * (1 - mu) ** 5;
/** 100 b μ(1 − μ)⁶, b = Schlick(F0, 1/7)(1 − t) / ((1/7)(6/7)⁶), F0 and t from the exact conductor at 1 and 1/7. */
const closedForm = (eta, k, deg) => {
  const f0 = fresnelConductor(1, eta, k);
  const tint = fresnelConductor(1 / 7, eta, k) / schlick(f0, 1 / 7);
  const mu = Math.cos((deg * Math.PI) / 180);
  return (100 * (schlick(f0, 1 / 7) * (1 - tint) * mu * (1 - mu) ** 6)) / ((1 / 7) * (6 / 7) ** 6);
};

describe('grader f82-schlick-gap', () => {
  it.each([
    ['aluminum', 'r', 80],
    ['gold', 'b', 70],
    ['iron', 'g', 85],
    ['copper', 'g', 60],
  ])('%s %s at %s°: 100 (Schlick − F82-tint) is the closed form 100 b μ(1 − μ)⁶', (metal, ch, deg) => {
    const [eta, k] = measuredRgbNk(metal)['rgb'.indexOf(ch)];
    expect(f82SchlickGap(metal, ch, deg).gap).toBeCloseTo(closedForm(eta, k, deg), 10);
  });

  const params = { metal: 'aluminum', channel: 'r', thetaDeg: 80 };
  const grade = (answer) => grader.grade({ answer, params, tolerance: 0.3, state: {} });
  const { gap, schlick: s, exact } = f82SchlickGap('aluminum', 'r', 80);

  it('passes the gap, fails a gap 0.4 points off, and names the slip of comparing with the exact curve', () => {
    expect(grade(gap).ok).toBe(true);
    expect(grade(gap + 0.4).ok).toBe(false);
    const slip = grade(100 * (s - exact));
    expect(slip.ok).toBe(false);
    expect(slip.details[0]).toMatch(/against the exact curve/);
    expect(grade(-gap).details[0]).toMatch(/sign/);
  });

  it('the shipped question is answerable from the three-digit F0 and tint the widget’s formula shows', () => {
    expect(exercise.grader).toBe('f82-schlick-gap');
    const { f0, tint } = f82SchlickGap('aluminum', 'r', 80);
    const [F0, t] = [Number(f0.toFixed(3)), Number(tint.toFixed(3))];
    const mu = Math.cos((80 * Math.PI) / 180);
    const byHand = (100 * schlick(F0, 1 / 7) * (1 - t) * mu * (1 - mu) ** 6) / ((1 / 7) * (6 / 7) ** 6);
    expect(Math.abs(byHand - gap)).toBeLessThan(exercise.tolerance / 3);
    // and it tells Schlick's error against the exact curve apart from the gap asked for
    expect(Math.abs(100 * (s - exact) - gap)).toBeGreaterThan(2 * exercise.tolerance);
  });
});
