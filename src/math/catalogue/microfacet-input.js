// @ts-check
// The one input every D and V term reads, the JS twin of shaders/microfacet-input.glsl (as Filament hands one
// per-pixel struct to its lobes): l, v and the half vector h in the tangent frame (t, b, n) = (x, y, z), the
// cosines n·l, n·v, n·h, l·h, sin²θh from the half vector itself (h.x² + h.y²: precise near n, where 1 - (n·h)²
// cancels) and the roughness pair (αx, αy), isotropic when equal. A term's `args` name its fields (FIELDS); the
// GLSL dispatch (src/core/gpu/term-chunks.js) passes each as FIELDS[arg].glsl, the parity and stress grids sweep
// each over its kind.
import { PARAMETERS } from './parameters.js';

/**
 * A field of the input: its GLSL expression over the struct `m`, and what the grids sweep it over: an angle
 * (kind: the angle grid's name), one component of a direction (dir, axis), or a shared parameter.
 * @typedef {{ glsl: string, kind?: string, dir?: 'l' | 'v' | 'h', axis?: number, param?: string }} InputField
 */

/** @param {'l' | 'v' | 'h'} dir @returns {Record<string, InputField>} */
const components = (dir) =>
  Object.fromEntries(['x', 'y', 'z'].map((c, axis) => [`${dir}${c}`, { glsl: `m.${dir}.${c}`, dir, axis }]));

/** @type {Record<string, InputField>} */
export const FIELDS = {
  nl: { glsl: 'm.nl', kind: 'nl' },
  nv: { glsl: 'm.nv', kind: 'nv' },
  nh: { glsl: 'm.nh', kind: 'nh' },
  lh: { glsl: 'm.lh', kind: 'lh' },
  sin2h: { glsl: 'm.sin2h', kind: 'sin2h' },
  ...components('l'),
  ...components('v'),
  ...components('h'),
  // an isotropic term's α is αx (equal to αy when the input is isotropic)
  alpha: { glsl: 'm.alpha.x', param: 'alpha' },
  alphaX: { glsl: 'm.alpha.x', param: 'alphaX' },
  alphaY: { glsl: 'm.alpha.y', param: 'alphaY' },
};

/** Whether an argument name is a field of the microfacet input. @param {string} arg */
export const isInputField = (arg) => Object.hasOwn(FIELDS, arg);

/**
 * @typedef {object} MicrofacetInput
 * @property {number[]} l unit, tangent frame
 * @property {number[]} v
 * @property {number[] | null} h null when l = -v
 * @property {number} nl
 * @property {number} nv
 * @property {number} nh
 * @property {number} lh
 * @property {number} sin2h h.x² + h.y²
 * @property {number[]} alpha [αx, αy]
 */

const dot = (/** @type {number[]} */ a, /** @type {number[]} */ b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * The input at unit l, v (tangent frame) and roughness α, a number (isotropic) or [αx, αy].
 * @param {number[]} l
 * @param {number[]} v
 * @param {number | number[]} alpha
 * @returns {MicrofacetInput}
 */
export function microfacetInput(l, v, alpha) {
  const sum = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const len = Math.hypot(...sum);
  const h = len > 1e-12 ? sum.map((x) => x / len) : null;
  return {
    l,
    v,
    h,
    nl: l[2],
    nv: v[2],
    nh: h ? h[2] : 0,
    lh: h ? dot(l, h) : 0,
    sin2h: h ? h[0] * h[0] + h[1] * h[1] : 1,
    alpha: Array.isArray(alpha) ? alpha : [alpha, alpha],
  };
}

/**
 * The value of one argument of a term at an input: a field of it, or else the parameter of that name in p.
 * @param {MicrofacetInput} m
 * @param {Record<string, number>} p
 * @param {string} arg
 */
export function argumentAt(m, p, arg) {
  const field = FIELDS[arg];
  if (!field) return p[arg];
  if (field.dir) return /** @type {number[]} */ (m[field.dir] ?? [0, 0, 1])[/** @type {number} */ (field.axis)];
  if (field.param) return arg === 'alphaY' ? m.alpha[1] : m.alpha[0];
  return /** @type {number} */ (m[/** @type {'nl' | 'nv' | 'nh' | 'lh' | 'sin2h'} */ (arg)]);
}

/** The shared parameter a field sweeps over (alpha, alphaX, alphaY), if any. @param {string} arg */
export const fieldParam = (arg) => {
  const name = FIELDS[arg]?.param;
  return name ? PARAMETERS[name] : undefined;
};

/**
 * A D or V term at an input, as the GLSL dispatch calls it: its js over its args (each argumentAt), then its
 * normaliser of the parameters after the first argument.
 * @param {import('./types.js').TermEntry} entry
 * @param {MicrofacetInput} m
 * @param {Record<string, number>} p
 */
export function termAt(entry, m, p) {
  if (!entry.js) throw new Error(`catalogue: ${entry.key} has no function`);
  const args = entry.args.map((arg) => argumentAt(m, p, arg));
  return entry.normaliser ? entry.js(...args, entry.normaliser(...args.slice(1))) : entry.js(...args);
}
