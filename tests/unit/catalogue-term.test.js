// The catalogue's builder term(): the fields it derives are the ones the hand-written families spell out, and
// what an entry states wins.
import { describe, expect, it } from 'vitest';
import { CATALOGUE } from '../../src/math/catalogue/index.js';
import { screamingSnake, term, terms } from '../../src/math/catalogue/term.js';

const OWN = { label: 'Made up', cite: 'Nobody 2026', js: null, evaluate: null, glsl: null, args: [], params: {} };

describe('term(): key, short, chunk and define derive; stated fields win', () => {
  it('derives every define the fresnel, visibility and compensation modules spell out by hand', () => {
    const spelled = ['fresnel', 'visibility', 'compensation'].flatMap((f) =>
      Object.values(CATALOGUE[f].terms)
        .filter((e) => e.define)
        .map((e) => [CATALOGUE[f].definePrefix, e.key, e.define]),
    );
    expect(spelled.length).toBeGreaterThan(8);
    for (const [prefix, key, define] of spelled) expect(`${prefix}_${screamingSnake(key)}`).toBe(define);
  });
  it('fills key, short (= label), chunk (the family’s) and define', () => {
    const entry = term({ definePrefix: 'NDF', chunk: 'ndf.glsl' }, 'shiftedGamma2', OWN);
    expect(entry).toEqual({
      ...OWN,
      key: 'shiftedGamma2',
      short: 'Made up',
      chunk: 'ndf.glsl',
      define: 'NDF_SHIFTED_GAMMA2',
    });
  });
  it('keeps a stated short, chunk or define, null included', () => {
    const own = { ...OWN, short: 'MU', chunk: 'other.glsl', define: null };
    expect(term({ definePrefix: 'X', chunk: 'x.glsl' }, 'k', own)).toEqual({ ...own, key: 'k' });
  });
  it('terms() keeps the menu order and keys each entry by its property', () => {
    const built = terms({ definePrefix: 'D', chunk: null }, { b: OWN, a: OWN });
    expect(Object.keys(built)).toEqual(['b', 'a']);
    expect(built.a.key).toBe('a');
  });
});
