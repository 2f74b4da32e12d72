// The JS half of `npm run stress`: every exported function of src/math over the inputs of
// stress-domains.js, counting NaN, Inf and values outside the documented range.
import * as M from '../../src/math/index.js';
import { STRESS_DOMAINS } from './stress-domains.js';

const cartesian = (lists) => lists.reduce((acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);

/** Every number inside a result (numbers, arrays, objects of numbers; null counts as nothing). */
function numbersIn(value) {
  if (typeof value === 'number') return [value];
  if (value === null || typeof value !== 'object') return [];
  return Object.values(value).flatMap(numbersIn);
}

function inputsOf(name, spec) {
  if (spec.pairs) {
    const params = spec.params ?? [undefined];
    return spec.pairs.flatMap(([l, v]) =>
      params.map((p) => (p === undefined ? [l, v] : spec.use ? [l, v, p, spec.use] : [l, v, p])),
    );
  }
  return spec.tuples ?? cartesian(spec.args);
}

export function sweepJs({ limit = Infinity } = {}) {
  const rows = [];
  const unclassified = Object.keys(M).filter(
    (k) => typeof M[k] === 'function' && !(k in STRESS_DOMAINS) && !(k in STRESS_DOMAINS.skipped),
  );
  for (const [name, spec] of Object.entries(STRESS_DOMAINS)) {
    if (name === 'skipped') continue;
    const inputs = inputsOf(name, spec).slice(0, limit);
    let nan = 0;
    let inf = 0;
    let outside = 0;
    let worst = null;
    for (const args of inputs) {
      const result = (spec.fn ?? M[name])(...args);
      const out = spec.pick ? spec.pick.map((k) => result[k]) : result;
      if (result === null && spec.nullable) continue;
      for (const x of numbersIn(out)) {
        const bad = Number.isNaN(x)
          ? 'nan'
          : !Number.isFinite(x) && spec.range[1] !== Infinity
            ? 'inf'
            : x < spec.range[0] || x > spec.range[1]
              ? 'outside'
              : null;
        if (!bad && (Number.isFinite(x) || spec.allowInfinity)) continue;
        if (bad === 'nan') nan++;
        else if (bad === 'inf' || !Number.isFinite(x)) inf++;
        else outside++;
        worst ??= { args, value: x };
      }
    }
    rows.push({ name, inputs: inputs.length, range: spec.range, nan, inf, outside, worst });
  }
  // the data lookups: every table material through both conductor models
  for (const key of [...M.METALS, ...M.NON_METALS].map((m) => m.key)) {
    for (const model of Object.keys(M.CONDUCTOR_MODELS)) {
      const p = M.fresnelParams(key, model);
      const bad = [...p.eta, ...p.k, ...p.f0].filter((x) => !Number.isFinite(x) || x < 0).length;
      rows.push({
        name: `fresnelParams(${key}, ${model})`,
        inputs: 1,
        range: [0, Infinity],
        nan: 0,
        inf: 0,
        outside: bad,
        worst: null,
      });
    }
  }
  return { rows, unclassified };
}
