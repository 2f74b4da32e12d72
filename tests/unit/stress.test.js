// The test-suite version of `npm run stress` (JS half; the GLSL half is the parity test's invalid count):
// every export of src/math is classified, and none returns NaN, Inf or a value outside its range.
import { describe, expect, it } from 'vitest';
import { sweepJs } from '../support/stress-sweep.js';

describe('numerical stress (JS)', () => {
  const { rows, unclassified } = sweepJs({ limit: 400 });
  it('classifies every exported function', () => expect(unclassified).toEqual([]));
  for (const r of rows) {
    it(`${r.name}: no NaN, Inf or value outside [${r.range.join(', ')}] over ${r.inputs} inputs`, () => {
      expect({ nan: r.nan, inf: r.inf, outside: r.outside, example: r.worst }).toEqual({
        nan: 0,
        inf: 0,
        outside: 0,
        example: null,
      });
    });
  }
});
