// The NDF explorer's note under the log plot names the longest tail: recomputed here from src/math/ndf.js at the
// matched widths (src/math/ndf-width.js), D(60°)/D(0) per NDF, the largest named.
import { describe, expect, it } from 'vitest';
import { ndfABC, ndfBeckmann, ndfBlinnPhong, ndfGGX, ndfSGD } from '../../src/math/ndf.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';
import { termLabel } from '../../src/math/catalogue/index.js';
import { TAIL_DEG, ndfCurves, tailsAt } from '../../src/widgets/ndf-explorer/model.js';
import { describeTails } from '../../src/widgets/ndf-explorer/words.js';
import { schema } from '../../src/widgets/ndf-explorer/schema.js';

const escape = (text) => text.replace(/[()]/g, '\\$&');
const DEFAULTS = Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default]));
const D = {
  ggx: (c, p) => ndfGGX(c, p.alpha),
  beckmann: (c, p) => ndfBeckmann(c, p.alpha),
  blinnPhong: (c, p) => ndfBlinnPhong(c, p.exponent),
  abc: (c, p) => ndfABC(c, p.a1, p.a2),
  sgd: (c, p) => ndfSGD(c, p.alpha, p.p),
};

/** The NDF with the most of its peak left at 60°, straight from the NDF functions. */
function longestByNdf(state) {
  const params = matchNdfWidths(state.hwhm, state);
  const c = Math.cos((60 * Math.PI) / 180);
  const ratios = state.D.map((key) => [key, D[key](c, params[key]) / D[key](1, params[key])]);
  return ratios.reduce((best, r) => (r[1] > best[1] ? r : best));
}

describe('the longest tail, said under the log plot', () => {
  const cases = [
    { hwhm: 8 },
    { hwhm: 1 },
    { hwhm: 40 },
    { hwhm: 8, abcA2: 0.5 },
    { hwhm: 20, sgdP: 1.9 },
    { hwhm: 8, D: ['beckmann', 'blinnPhong', 'sgd'] },
  ];
  for (const change of cases) {
    it(`is the NDF src/math/ndf.js gives the largest D(60°)/D(0) at ${JSON.stringify(change)}`, () => {
      const state = { ...DEFAULTS, ...change };
      const [key, ratio] = longestByNdf(state);
      const text = describeTails(tailsAt(ndfCurves(state)), state, TAIL_DEG);
      expect(TAIL_DEG).toBe(60);
      const named = escape(termLabel('ndf', key));
      expect(text).toMatch(new RegExp(`^Longest tail at a half width of ${state.hwhm}°: ${named}\\.`));
      const [mantissa, power] = ratio.toExponential(1).split('e');
      expect(text).toContain(`it still has ${mantissa} × 10`);
      expect(text).toContain([...String(Number(power))].map((ch) => '⁻⁰¹²³⁴⁵⁶⁷⁸⁹'['-0123456789'.indexOf(ch)]).join(''));
    });
  }
  it('at the default 8°, GGX: the talk’s long-tailed distribution (Walter et al. 2007)', () => {
    expect(longestByNdf(DEFAULTS)[0]).toBe('ggx');
  });
});
