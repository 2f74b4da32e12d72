// @ts-check
// Stress inputs of a term, from its entry: each parameter's range (its ends, beyond both where the functions
// clamp) and between them its delicate values, or without those the decades or quarters of the range; the angles
// from the caller, who knows which values stress its arithmetic (float32 on the GPU, float64 in `npm run stress`).

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
 * Every argument tuple of a term's function (entry.args in order), the cartesian product of each argument's
 * values: a parameter's paramStress, an angle's angleValues(kind, dims) with dims the number of dimensions of the
 * product (callers take coarser grids when it is large). A 'cos' followed by 'sin2' is one dimension, the pairs
 * (cos θ, sin²θ) over angleValues('theta', dims), as a half vector gives them.
 * @param {import('./types.js').TermEntry} entry
 * @param {(kind: string, dims: number) => number[]} angleValues
 * @returns {number[][]}
 */
export function termInputs(entry, angleValues) {
  const paired = (/** @type {number} */ i) => entry.args[i] === 'cos' && entry.args[i + 1] === 'sin2';
  const kinds = entry.args.filter((arg, i) => arg !== 'sin2' || !paired(i - 1));
  const dims = kinds.length;
  const axes = kinds.map((arg) => {
    if (arg in entry.params) return paramStress(entry.params[arg]).map((x) => [x]);
    if (arg === 'cos' && paired(entry.args.indexOf('cos')))
      return angleValues('theta', dims).map((t) => [Math.cos(t), Math.sin(t) ** 2]);
    return angleValues(arg, dims).map((x) => [x]);
  });
  return axes.reduce((acc, axis) => acc.flatMap((a) => axis.map((x) => [...a, ...x])), [[]]);
}
