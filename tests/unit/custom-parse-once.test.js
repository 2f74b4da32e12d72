// A user's code is parsed once per edit: the runner, the GPU evaluation and the panel's sliders ask the same
// cached verdict (parse.js keeps it by slot and code) instead of running the GLSL parser each.
import { describe, expect, it } from 'vitest';
import { parseCount, parseCustom } from '../../src/core/custom/parse.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { createCustomRunner, sliderValues } from '../../src/core/custom/custom-panel-run.js';
import { evaluateCustom } from '../../src/core/custom/gpu-eval.js';
import { trustCode } from '../../src/core/custom/custom-panel-trust.js';

/** A renderer whose context is gone: the runner and evaluateCustom stop before the GPU, after their checks. */
const lostRenderer = { getContext: () => ({ isContextLost: () => true }) };

const edited = (n) =>
  SLOTS.D.starter.replace(/\{/, `{\n  float k${n} = 1.0; // edit ${n}`).replace('return ', `return k${n} * `);

describe('a user-written term is parsed once per edit', () => {
  it('one parse for the code of an edit, however many callers ask (the runner, the evaluation, the sliders)', () => {
    const runner = createCustomRunner(() => null);
    const plan = { key: 'alpha 0.3', inputs: [[0.9, 0.3]], read: (out) => out };
    runner.run('D', SLOTS.D.starter, {}, plan); // the starter, the runner's fallback, is parsed once for the page
    for (const n of [1, 2, 3]) {
      const code = edited(n);
      trustCode(code); // typed by the user: it may run at once
      const before = parseCount();
      const { status } = runner.run('D', code, {}, plan);
      expect(status.problems).toEqual([]);
      expect(evaluateCustom(lostRenderer, 'D', code, {}, plan.inputs)).toEqual({
        errors: [{ line: 0, message: 'the WebGL context is lost' }],
      });
      sliderValues(parseCustom('D', code).params, {}); // the panel's sliders
      parseCustom('D', code); // and the panel's problems
      expect(parseCount() - before).toBe(1);
    }
  });

  it('gives every caller the same verdict, frozen, and parses a changed code afresh', () => {
    const code = edited(4);
    const first = parseCustom('D', code);
    expect(parseCustom('D', code)).toBe(first);
    expect(Object.isFrozen(first) && Object.isFrozen(first.problems) && Object.isFrozen(first.params)).toBe(true);
    const before = parseCount();
    const broken = parseCustom('D', code.replace('return', 'retrun'));
    expect(broken.ok).toBe(false);
    expect(parseCount() - before).toBe(1);
    expect(parseCustom('V', SLOTS.V.starter).ok).toBe(true); // by slot and code: another slot's code is its own
  });
});
