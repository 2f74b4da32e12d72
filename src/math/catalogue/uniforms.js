// @ts-check
// Each uniform bound to its parameter: the values a view's program reads for a choice of terms, from one object
// of parameter values ({ alpha, exponent, a1, a2, p, f0, … }, the one NDF_TERMS and VISIBILITY_TERMS read). A view
// no longer maps parameters to uniform names by hand, and a normaliser (SGD's Γ(1 - p, α)) is computed here, once
// per draw, from the parameters its entry names.
import { CATALOGUE } from './index.js';
import { PARAMETERS } from './parameters.js';

/** @typedef {import('./index.js').TermChoice} TermChoice */

const FAMILY_OF_CHOICE = Object.fromEntries(Object.values(CATALOGUE).map((f) => [f.choice, f]));

/**
 * The uniforms of the chosen terms' own parameters and normalisers, name → value, from `values` (a parameter
 * missing from it takes its `default`; an entry without a define, the user's code, reads none here).
 * @param {TermChoice} choice
 * @param {Record<string, number>} values
 * @returns {Record<string, number>}
 */
export function termUniforms(choice, values) {
  /** @type {Record<string, number>} */
  const out = {};
  for (const [slot, key] of Object.entries(choice)) {
    const entry = key === undefined ? undefined : FAMILY_OF_CHOICE[slot]?.terms[key];
    if (!entry) continue;
    const value = (/** @type {string} */ name) =>
      values[name] ?? entry.params[name]?.default ?? entry.params[name]?.min;
    for (const [name, param] of Object.entries(entry.params))
      if (param.uniform && !Object.hasOwn(PARAMETERS, name)) out[param.uniform] = value(name);
    if (entry.normaliser && entry.normaliserUniform)
      out[entry.normaliserUniform] = entry.normaliser(...entry.args.slice(1).map(value));
  }
  return out;
}

/**
 * The uniforms of the shared parameters (uAlpha, uF0, uDiffuse, uSigma), name → value, from `values`.
 * @param {Record<string, number | number[]>} values
 * @returns {Record<string, number | number[]>}
 */
export function sharedUniforms(values) {
  /** @type {Record<string, number | number[]>} */
  const out = {};
  for (const [name, param] of Object.entries(PARAMETERS))
    if (param.uniform && values[name] !== undefined) out[param.uniform] = values[name];
  return out;
}

/**
 * Every term uniform any choice may read, with its default (normalisers at the shared `values`, e.g. { alpha }):
 * what a program that may draw any term declares.
 * @param {Record<string, number>} [values]
 * @returns {Record<string, number>}
 */
export function termUniformDefaults(values = {}) {
  /** @type {Record<string, number>} */
  const out = {};
  for (const family of Object.values(CATALOGUE))
    for (const key of Object.keys(family.terms)) Object.assign(out, termUniforms({ [family.choice]: key }, values));
  return out;
}
