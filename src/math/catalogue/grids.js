// @ts-check
// Stress inputs of a term, from its entry: each parameter's range (its ends, beyond both where the functions
// clamp) and between them its delicate values, or without those the decades or quarters of the range; the angles
// from the caller, who knows which values stress its arithmetic (float32 on the GPU, float64 in `npm run stress`).
import { FIELDS, fieldParam } from './microfacet-input.js';

/** lo, 10 lo, 100 lo, … below hi, each rounded to 12 digits (1e-4 · 10 is not 1e-3 in binary). */
/** @param {number} lo @param {number} hi */
const decades = (lo, hi) => {
  const out = [];
  for (let i = 0; lo * 10 ** i < hi; i++) out.push(Number((lo * 10 ** i).toPrecision(12)));
  return out;
};

/**
 * The stress values of one parameter, ascending, without repeats.
 * @param {import('./types.js').TermParam} param
 * @returns {number[]}
 */
export function paramStress({ min, max, clamped = false, delicate = [] }) {
  const span = max - min;
  let inside = delicate;
  if (!delicate.length && min > 0 && max / min >= 100) inside = decades(min, max);
  else if (!delicate.length && min === 0 && max >= 100) inside = decades(1, max);
  else if (!delicate.length) inside = [1, 2, 3].map((i) => min + (span * i) / 4);
  const beyond = clamped ? [min > 0 ? 0 : min - span / 2, max * 2] : [];
  return [...new Set([min, ...inside, max, ...beyond])].sort((a, b) => a - b);
}

/**
 * The parameter an argument sweeps over: the term's own, else the shared one of its input field (αx, αy).
 * @param {import('./types.js').TermEntry} entry
 * @param {string} arg
 */
export const argParam = (entry, arg) => (Object.hasOwn(entry.params, arg) ? entry.params[arg] : fieldParam(arg));

/**
 * The arguments of a term grouped into the dimensions of its grid: one argument alone; 'nh' then 'sin2h', the
 * pairs (cos θh, sin²θh) one half vector gives; the three components of one direction of the microfacet input
 * ('hx', 'hy', 'hz'), the unit vectors of that direction's grid.
 * @param {string[]} args
 * @returns {{ kind: string, args: string[] }[]}
 */
export function argGroups(args) {
  /** @type {{ kind: string, args: string[] }[]} */
  const groups = [];
  for (let i = 0; i < args.length; i++) {
    const dir = FIELDS[args[i]]?.dir;
    const triple = dir && args.slice(i, i + 3).join() === [`${dir}x`, `${dir}y`, `${dir}z`].join();
    if (args[i] === 'nh' && args[i + 1] === 'sin2h') groups.push({ kind: 'theta', args: args.slice(i, ++i + 1) });
    else if (triple) groups.push({ kind: `dir:${dir}`, args: args.slice(i, (i += 2) + 1) });
    else groups.push({ kind: args[i], args: [args[i]] });
  }
  return groups;
}

/**
 * Every argument tuple of a term's function (entry.args in order), the cartesian product of each dimension's
 * values (argGroups): a parameter's paramStress (the term's own or its field's shared one), an angle's
 * angleValues(kind, dims) with dims the number of dimensions of the product (callers take coarser grids when it
 * is large); a half vector's pairs (cos θ, sin²θ) over angleValues('theta', dims); a direction's unit vectors
 * angleValues('dir:h', dims) (each [x, y, z]).
 * @param {import('./types.js').TermEntry} entry
 * @param {(kind: string, dims: number) => any[]} angleValues
 * @returns {number[][]}
 */
export function termInputs(entry, angleValues) {
  const groups = argGroups(entry.args);
  const dims = groups.length;
  const axes = groups.map(({ kind, args }) => {
    const param = args.length === 1 ? argParam(entry, args[0]) : undefined;
    if (param) return paramStress(param).map((x) => [x]);
    if (kind === 'theta') return angleValues('theta', dims).map((t) => [Math.cos(t), Math.sin(t) ** 2]);
    if (kind.startsWith('dir:')) return angleValues(kind, dims);
    return angleValues(kind, dims).map((x) => [x]);
  });
  return axes.reduce((acc, axis) => acc.flatMap((a) => axis.map((x) => [...a, ...x])), [[]]);
}
