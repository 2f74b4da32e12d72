// The width search without the SGD normaliser, and the SGD normaliser passed in rather than integrated per call.
import { describe, expect, it } from 'vitest';
import { matchNdfWidths, ndfHalfWidthDeg } from '../../src/math/ndf-width.js';
import { ndfABC, ndfBeckmann, ndfGGX, ndfSGD, sgdNormalization } from '../../src/math/ndf.js';
import { NDF_FAMILY } from '../../src/math/catalogue/ndf-terms.js';

/** The normalised NDFs, as NDF_TERMS evaluate them (the SGD integrating its normaliser Γ(1 - p, alpha) itself). */
const NORMALISED = {
  ggx: (c, m) => ndfGGX(c, m.alpha),
  beckmann: (c, m) => ndfBeckmann(c, m.alpha),
  abc: (c, m) => ndfABC(c, m.a1, m.a2),
  sgd: (c, m) => ndfSGD(c, m.alpha, m.p),
};

describe('matchNdfWidths without the cancelling normaliser', () => {
  // from 5°: below, SGD's width alpha (clamped to 0.01) cannot make the lobe narrow enough at p = 0
  for (const hwhm of [5, 12.5, 30, 40]) {
    for (const sgdP of [0, 0.64, 1.5]) {
      it(`the half width of the normalised D at the solved parameters is ${hwhm}° to 1e-12° (SGD p = ${sgdP})`, () => {
        const m = matchNdfWidths(hwhm, { abcA2: 2.5, sgdP });
        for (const [key, D] of Object.entries(NORMALISED)) {
          expect(Math.abs(ndfHalfWidthDeg((c) => D(c, m[key])) - hwhm), key).toBeLessThan(1e-12);
        }
      });
    }
  }
});

describe('the SGD normaliser computed once', () => {
  it('ndfSGD with the catalogue normaliser passed in equals ndfSGD integrating it (Simpson, sgdNormalization)', () => {
    const normaliser = NDF_FAMILY.terms.sgd.normaliser;
    for (const [alpha, p] of [
      [0.01, 0],
      [0.05, 0.64],
      [0.5, 1.5],
      [2, 1.9],
      [3, -1],
    ]) {
      const norm = normaliser?.(alpha, p) ?? NaN;
      expect(norm).toBe(sgdNormalization(Math.min(Math.max(alpha, 0.01), 2), Math.min(Math.max(p, 0), 1.9)));
      for (const c of [1e-3, 0.3, 0.9, 1]) expect(ndfSGD(c, alpha, p, norm)).toBe(ndfSGD(c, alpha, p));
    }
  });
});
