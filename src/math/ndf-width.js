// Putting NDFs side by side at the same width. The width of a distribution here is its half width at half
// maximum (HWHM): the angle theta_h at which D falls to half of D(n). Each NDF's width parameter is solved
// for by bisection so that all five share one HWHM; the shape parameters (ABC's a2, SGD's p) stay as chosen.
import { ndfABC, ndfBeckmann, ndfGGX, ndfSGD } from './ndf.js';
import { DEG } from './angles.js';
import { NDF_FAMILY } from './catalogue/ndf-terms.js';

/** HWHM in degrees of D(cos), a function decreasing in theta_h. */
export function ndfHalfWidthDeg(D) {
  const half = D(1) / 2;
  let lo = 0;
  let hi = 90;
  for (let i = 0; i < 60; i++) {
    const mid = (lo + hi) / 2;
    if (D(Math.cos(mid * DEG)) > half) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

/** The x in [lo, hi] (searched on a log scale) where width(x) = target; width increasing (or decreasing) in x. */
function solveLog(width, target, lo, hi) {
  const rising = width(hi) > width(lo);
  let [a, b] = [Math.log(lo), Math.log(hi)];
  for (let i = 0; i < 60; i++) {
    const m = (a + b) / 2;
    if (width(Math.exp(m)) < target === rising) a = m;
    else b = m;
  }
  return Math.exp((a + b) / 2);
}

const MATCHED_HERE = { ggx: 1, beckmann: 1, blinnPhong: 1, abc: 1, sgd: 1 };

/**
 * Any other NDF of the catalogue: its width parameter (its first) solved for, the others at mid-range. The search
 * runs over the parameter's range on a log scale (from 1e-6 when the range starts at 0). An NDF without one reads
 * its width from the microfacet input's (αx, αy) (an anisotropic lobe): {}, GGX's α for both.
 */
function matchWidthParam(term, hwhmDeg) {
  if (!Object.keys(term.params).length) return {};
  const [[name, range], ...others] = Object.entries(term.params);
  const fixed = Object.fromEntries(others.map(([key, p]) => [key, (p.min + p.max) / 2]));
  const width = (x) => ndfHalfWidthDeg((c) => term.evaluate(c, { ...fixed, [name]: x }));
  return { ...fixed, [name]: solveLog(width, hwhmDeg, Math.max(range.min, 1e-6), range.max) };
}

/** An object whose properties are each computed when first read, then kept (a widget reads only those it shows). */
function lazyRecord(solvers) {
  const out = {};
  for (const [key, solve] of Object.entries(solvers)) {
    let value;
    Object.defineProperty(out, key, { enumerable: true, get: () => (value ??= solve()) });
  }
  return out;
}

/**
 * Parameters that give every NDF the half width `hwhmDeg` (1°–40°):
 * { ggx: { alpha }, beckmann: { alpha }, blinnPhong: { exponent }, abc: { a1, a2 }, sgd: { alpha, p } }, and
 * for every other NDF of the catalogue its parameters by matchWidthParam. Each NDF is solved when first read.
 */
export function matchNdfWidths(hwhmDeg, { abcA2 = 2.5, sgdP = 0.64 } = {}) {
  const w = (D) => ndfHalfWidthDeg(D);
  return lazyRecord({
    ggx: () => ({ alpha: solveLog((a) => w((c) => ndfGGX(c, a)), hwhmDeg, 1e-3, 1) }),
    beckmann: () => ({ alpha: solveLog((a) => w((c) => ndfBeckmann(c, a)), hwhmDeg, 1e-3, 1) }),
    blinnPhong: () => ({ exponent: Math.log(0.5) / Math.log(Math.cos(hwhmDeg * DEG)) }), // closed form: cos^p = 1/2
    abc: () => ({ a1: solveLog((a1) => w((c) => ndfABC(c, a1, abcA2)), hwhmDeg, 0.01, 1e4), a2: abcA2 }),
    // the normaliser Γ(1 - p, alpha) cancels in the half width (D against D(1)/2): 1 in its place
    sgd: () => ({ alpha: solveLog((a) => w((c) => ndfSGD(c, a, sgdP, 1)), hwhmDeg, 0.01, 2), p: sgdP }),
    ...Object.fromEntries(
      Object.values(NDF_FAMILY.terms)
        .filter((term) => !(term.key in MATCHED_HERE))
        .map((term) => [term.key, () => matchWidthParam(term, hwhmDeg)]),
    ),
  });
}

/**
 * The parameters of NDF `kind` whose half width matches GGX at roughness alpha, so that one roughness
 * slider drives every NDF comparably. Returns the { alpha, exponent, a1, a2, p } object NDF_TERMS read.
 */
export function ndfParamsMatchingGGX(kind, alpha, shapes) {
  if (kind === 'ggx') return { alpha };
  const m = matchNdfWidths(
    ndfHalfWidthDeg((c) => ndfGGX(c, alpha)),
    shapes,
  );
  // NDFs without an alpha keep GGX's, which the visibility terms read
  return {
    alpha: m[kind].alpha ?? alpha,
    exponent: m.blinnPhong.exponent,
    a1: m.abc.a1,
    a2: m.abc.a2,
    p: m.sgd.p,
    ...m[kind],
  };
}
