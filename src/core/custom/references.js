// @ts-check
// The catalogue terms a slot's code can be compared with, evaluated in float64 (src/math through the catalogue) at
// the float32-rounded inputs the GPU saw, so a difference is the user's code's own. A term is offered when the
// slot's arguments determine it: D by n·h and α (Blinn–Phong with p = 2/α² − 2, Walter et al. 2007), V by n·l, n·v
// and α, F by F0 (the exact dielectric with the η that has that F0), a diffuse term by c_diff, l, v and α (σ = α in
// radians for Oren–Nayar, F0 = 0.04), a whole BRDF by l and v (the diffuse terms at c_diff = 1, σ = 0.3, F0 = 0.04).
import { CATALOGUE } from '../../math/catalogue/index.js';
import { blinnPhongExponentFromBeckmannAlpha } from '../../math/ndf.js';
import { ndfBeckmannAniso, ndfGGXAniso, visibilitySmithGGXCorrelatedAniso } from '../../math/anisotropic.js';
import { slotOf } from './slots.js';

/** @typedef {(input: number[]) => number[]} ReferenceFunction  one input of the slot (float32-rounded) → 1 or 3 */

/**
 * A term's float64 function in its family's calling convention (every term offered here has one).
 * @param {import('../../math/catalogue/types.js').TermEntry} term
 * @returns {import('../../math/catalogue/types.js').TermFunction}
 */
const evaluator = (term) => {
  if (!term.evaluate) throw new Error(`custom: catalogue term ${term.key} has no float64 function`);
  return term.evaluate;
};
const NDF = CATALOGUE.ndf.terms;
const FRESNEL = CATALOGUE.fresnel.terms;

/** The η of a dielectric whose F0 is f0 (F0 = ((η − 1)/(η + 1))²). @param {number} f0 */
const etaFromF0 = (f0) => (1 + Math.sqrt(f0)) / (1 - Math.sqrt(f0));

/** The cosine of the azimuth between l and v (1 when either is along n, where it does not matter). */
const cosPhiOf = (/** @type {number[]} */ l, /** @type {number[]} */ v) => {
  const s = Math.hypot(l[0], l[1]) * Math.hypot(v[0], v[1]);
  return s > 0 ? Math.min(Math.max((l[0] * v[0] + l[1] * v[1]) / s, -1), 1) : 1;
};

/** @type {Record<string, Record<string, ReferenceFunction>>} by slot, by catalogue key */
const BY_SLOT = {
  D: {
    ggx: ([nh, alpha]) => [evaluator(NDF.ggx)(nh, { alpha })],
    beckmann: ([nh, alpha]) => [evaluator(NDF.beckmann)(nh, { alpha })],
    blinnPhong: ([nh, alpha]) => [
      evaluator(NDF.blinnPhong)(nh, { exponent: blinnPhongExponentFromBeckmannAlpha(alpha) }),
    ],
  },
  DAniso: {
    ggxAniso: ([hx, hy, hz, ax, ay]) => [ndfGGXAniso(hx, hy, hz, ax, ay)],
    beckmannAniso: ([hx, hy, hz, ax, ay]) => [ndfBeckmannAniso(hx, hy, hz, ax, ay)],
  },
  VAniso: {
    smithGGXCorrelatedAniso: ([lx, ly, lz, vx, vy, vz, ax, ay]) => [
      visibilitySmithGGXCorrelatedAniso(lx, ly, lz, vx, vy, vz, ax, ay),
    ],
  },
  V: Object.fromEntries(
    Object.values(CATALOGUE.visibility.terms)
      .filter((t) => t.args.every((a) => ['nl', 'nv', 'alpha'].includes(a)))
      .map((t) => [t.key, ([nl, nv, alpha]) => [evaluator(t)({ nl, nv, nh: NaN, lh: NaN }, { alpha })]]),
  ),
  F: {
    schlick: ([r, g, b, lh]) => [r, g, b].map((f0) => evaluator(FRESNEL.schlick)(lh, { f0 })),
    one: () => [1, 1, 1],
    dielectric: ([r, g, b, lh]) =>
      [r, g, b].map((f0) => (f0 >= 1 ? 1 : evaluator(FRESNEL.dielectric)(lh, { eta: etaFromF0(f0) }))),
  },
  diffuse: Object.fromEntries(
    Object.values(CATALOGUE.diffuse.terms).map((t) => [
      t.key,
      ([cdiff, lx, ly, lz, vx, vy, vz, alpha]) => {
        const value = evaluator(t)(lz, vz, cosPhiOf([lx, ly], [vx, vy]), { cdiff, f0: 0.04, sigma: alpha });
        return [value, value, value];
      },
    ]),
  ),
  brdf: Object.fromEntries(
    Object.values(CATALOGUE.diffuse.terms).map((t) => [
      t.key,
      ([lx, ly, lz, vx, vy, vz]) => {
        const value = evaluator(t)(lz, vz, cosPhiOf([lx, ly], [vx, vy]), { cdiff: 1, f0: 0.04, sigma: 0.3 });
        return [value, value, value];
      },
    ]),
  ),
};

/** The family of the anisotropic slots' references (their slots stand beside no family's menu: slots.js). */
/** @type {Record<string, 'ndf' | 'visibility'>} */
const ANISOTROPIC_FAMILY = { DAniso: 'ndf', VAniso: 'visibility' };

const FAMILY_LABEL = { brdf: ' (c_diff = 1, σ = 0.3, F0 = 0.04)', diffuse: ' (σ = α, F0 = 0.04)' };

/**
 * The references a slot offers, key → label (the catalogue's labels).
 * @param {string} slotKey
 * @returns {Record<string, string>}
 */
export function referenceOptions(slotKey) {
  const slot = slotOf(slotKey);
  const family = CATALOGUE[ANISOTROPIC_FAMILY[slot.key] ?? slot.family ?? 'diffuse'];
  const suffix = /** @type {Record<string, string>} */ (FAMILY_LABEL)[slot.key] ?? '';
  return Object.fromEntries(Object.keys(BY_SLOT[slot.key]).map((key) => [key, family.terms[key].label + suffix]));
}

/**
 * The float64 reference of a slot by catalogue key, taking one input as the GPU saw it (rounded to float32 here).
 * @param {string} slotKey
 * @param {string} key a key of referenceOptions(slotKey)
 * @returns {ReferenceFunction}
 */
export function referenceFunction(slotKey, key) {
  const slot = slotOf(slotKey);
  const fn = Object.hasOwn(BY_SLOT[slot.key], key) ? BY_SLOT[slot.key][key] : null;
  if (!fn) throw new Error(`custom: ${slot.fn} has no reference '${key}' (${Object.keys(BY_SLOT[slot.key])})`);
  return (input) => fn(input.map(Math.fround));
}
