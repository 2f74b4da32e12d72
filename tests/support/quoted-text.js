// Reading the numbers a sentence quotes, for the tests that recompute them (quoted-figures, tour-figures).
import { expect } from 'vitest';
import { TOUR_STEPS } from '../../src/tour/steps.js';
import { inlineTexPlain } from '../../src/core/ui/inline-tex.js';

/** A tour step, its text as a reader sees it (each `$…$` formula as its plain fallback). */
export const stepText = (id) => {
  const step = TOUR_STEPS.find((s) => s.id === id);
  return { ...step, text: inlineTexPlain(step.text) };
};
/** The numbers the first match of `re` captures; fails if the sentence no longer reads that way. */
export function quoted(source, re) {
  const m = source.match(re);
  expect(m, `${re} in the text`).not.toBeNull();
  return m.slice(1).map(Number);
}
/** x printed with `digits` decimals reads `printed`. */
export const reads = (x, printed, digits = 0) => expect(x.toFixed(digits)).toBe(printed.toFixed(digits));
