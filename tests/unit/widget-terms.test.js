// Each widget's "Terms used" links to parity.html#fn-<name>; the parity page anchors the first row of each
// function (the first word of a PARITY_CASES name), so a term with no row is a dead link.
import { describe, expect, test } from 'vitest';
import { PARITY_CASES } from '../../src/core/gpu/parity-cases.js';
import { WIDGETS } from '../../src/widgets/registry.js';

const anchored = new Set(PARITY_CASES.map((c) => c.name.split(' ')[0]));

describe('widget "Terms used" lists', () => {
  const title = '%s names only functions with a row on the parity page (PARITY_CASES)';
  test.each(Object.keys(WIDGETS))(title, async (key) => {
    const { widget } = await WIDGETS[key].load();
    expect(Array.isArray(widget.terms)).toBe(true);
    expect(widget.terms.filter((t) => !anchored.has(t))).toEqual([]);
  });
});
