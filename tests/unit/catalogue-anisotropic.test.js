// The catalogue's anisotropic entries (issue 28): anisotropic GGX and Beckmann D and height-correlated Smith GGX V,
// each one entry that reads the whole microfacet input. Checked against the isotropic closed forms at αx = αy
// (Heitz 2014: the anisotropic forms reduce to them), against their own float64 functions through the dispatch, and
// for their rows on the parity page; and the α pair the hosts feed (uAlphaPair).
import { describe, expect, it } from 'vitest';
import { CATALOGUE, termDefines, termOptions } from '../../src/math/catalogue/index.js';
import { microfacetInput, termAt } from '../../src/math/catalogue/microfacet-input.js';
import { sharedUniforms } from '../../src/math/catalogue/uniforms.js';
import { PARITY_CASES } from '../../src/core/gpu/parity-cases.js';
import { termDispatchChunk } from '../../src/core/gpu/term-chunks.js';

const unit = (x, y, z) => [x, y, z].map((c) => c / Math.hypot(x, y, z));
/** GGX D (Walter et al. 2007) of n·h: α² / (π ((n·h)² (α² - 1) + 1)²). */
const ggx = (c, a) => (a * a) / (Math.PI * (c * c * (a * a - 1) + 1) ** 2);
/** Beckmann D: exp(-tan²θ / α²) / (π α² cos⁴θ). */
const beckmann = (c, a) => Math.exp(-(1 - c * c) / (c * c * a * a)) / (Math.PI * a * a * c ** 4);
/** Height-correlated Smith GGX as V = G2 / ((n·l)(n·v)) (Heitz 2014, eq. 99). */
const smithCorrelated = (nl, nv, a) => {
  const lambda = (c) => (Math.sqrt(1 + (a * a * (1 - c * c)) / (c * c)) - 1) / 2;
  return 1 / ((1 + lambda(nl) + lambda(nv)) * nl * nv);
};

const PAIRS = [
  [unit(0.5, 0.2, 0.8), unit(-0.3, 0.6, 0.5)],
  [unit(0.9, -0.1, 0.3), unit(0.1, 0.1, 1)],
];
const { ndf, visibility } = CATALOGUE;

describe('the anisotropic entries of the catalogue', () => {
  it('at αx = αy each is its isotropic closed form (GGX, Beckmann, Smith GGX height-correlated)', () => {
    for (const [l, v] of PAIRS)
      for (const a of [0.2, 0.5, 0.8]) {
        // (Beckmann cuts its far tail below e^-80 to 0)
        const m = microfacetInput(l, v, [a, a]);
        expect(termAt(ndf.terms.ggxAniso, m, {}) / ggx(m.nh, a)).toBeCloseTo(1, 11);
        expect(termAt(ndf.terms.beckmannAniso, m, {}) / beckmann(m.nh, a)).toBeCloseTo(1, 11);
        const V = termAt(visibility.terms.smithGGXCorrelatedAniso, m, {});
        expect(V / smithCorrelated(l[2], v[2], a)).toBeCloseTo(1, 11);
      }
  });

  it('with αx > αy the highlight stretches along t: D falls slower towards t than towards b', () => {
    const along = microfacetInput(unit(0.3, 0, 1), unit(0, 0, 1), [0.4, 0.1]);
    const across = microfacetInput(unit(0, 0.3, 1), unit(0, 0, 1), [0.4, 0.1]);
    for (const key of ['ggxAniso', 'beckmannAniso'])
      expect(termAt(ndf.terms[key], along, {})).toBeGreaterThan(5 * termAt(ndf.terms[key], across, {}));
  });

  it('the dispatch calls each over the input’s components; a menu offers them only when asked', () => {
    expect(termDefines({ D: 'ggxAniso', V: 'smithGGXCorrelatedAniso' })).toEqual({
      NDF_GGX_ANISO: 1,
      VIS_SMITH_GGX_CORRELATED_ANISO: 1,
    });
    expect(termDispatchChunk(ndf)).toContain(
      'float ndfTerm(MicrofacetInput m) { return ndfGGXAniso(m.h.x, m.h.y, m.h.z, m.alpha.x, m.alpha.y); }',
    );
    expect(termDispatchChunk(visibility)).toContain(
      'visibilitySmithGGXCorrelatedAniso(m.l.x, m.l.y, m.l.z, m.v.x, m.v.y, m.v.z, m.alpha.x, m.alpha.y)',
    );
    // the widgets that plot D over n·h alone do not offer a lobe that needs the tangent frame
    expect(termOptions('ndf')).not.toHaveProperty('ggxAniso');
    expect(termOptions('ndf', ['ggx', 'ggxAniso'])).toEqual({ ggx: 'GGX', ggxAniso: 'GGX, anisotropic' });
  });

  it('has rows on the parity page: its function over the catalogue’s grids, and through the dispatch', () => {
    const names = PARITY_CASES.map((c) => c.name);
    for (const name of [
      'ndfGGXAniso',
      'ndfBeckmannAniso',
      'visibilitySmithGGXCorrelatedAniso',
      'ndfTerm (NDF_GGX_ANISO)',
      'ndfTerm (NDF_BECKMANN_ANISO)',
      'visibilityTerm (VIS_SMITH_GGX_CORRELATED_ANISO)',
    ])
      expect(names, name).toContain(name);
    expect(new Set(names).size).toBe(names.length); // the vec3 forms' own rows are named apart
    const row = PARITY_CASES.find((c) => c.name === 'ndfGGXAniso');
    expect(row.args.some(([, , , ax, ay]) => ax === 1 && ay === 1e-4)).toBe(true);
  });

  it('the hosts’ α pair is one shared parameter, a vec2 uniform', () => {
    expect(sharedUniforms({ alpha: 0.3, alphaPair: [0.5, 0.1] })).toEqual({ uAlpha: 0.3, uAlphaPair: [0.5, 0.1] });
  });
});
