// @ts-check
// The catalogue's one builder of a term: an entry states what is its own (label, source, functions, arguments,
// parameters); its key, its #define, its shaders/ file and, when it is the label, its legend derive from the key
// and the family. The GLSL name stays spelled out: a minified bundle renames the JS functions.

/** @typedef {import('./types.js').TermEntry} TermEntry */

/**
 * What an entry states: every field of a TermEntry but those that derive (each may still be given to override).
 * @typedef {Omit<TermEntry, 'key' | 'short' | 'chunk' | 'define'> &
 *   Partial<Pick<TermEntry, 'short' | 'chunk' | 'define'>>} OwnTerm
 */

import { PARAMETERS } from './parameters.js';

/** The microfacet roughness α every isotropic D and V term reads (the shared table's, which has delicate values). */
export const ALPHA = /** @type {import('./types.js').TermParam & { delicate: number[] }} */ (PARAMETERS.alpha);

/**
 * A camelCase key in SCREAMING_SNAKE, as defines spell it: 'blinnPhong' → 'BLINN_PHONG', an acronym one word
 * ('smithGGXSeparable' → 'SMITH_GGX_SEPARABLE').
 * @param {string} key
 */
export const screamingSnake = (key) =>
  key
    .replace(/([a-z0-9])([A-Z])/g, '$1_$2')
    .replace(/([A-Z])([A-Z][a-z])/g, '$1_$2')
    .toUpperCase();

/**
 * The entry of key in a family: short = label, chunk = the family's, define = `<definePrefix>_<KEY>`, unless
 * stated.
 * @param {{ definePrefix: string, chunk: string | null }} family
 * @param {string} key
 * @param {OwnTerm} own
 * @returns {TermEntry}
 */
export function term({ definePrefix, chunk }, key, own) {
  return { key, short: own.label, chunk, define: `${definePrefix}_${screamingSnake(key)}`, ...own };
}

/**
 * A family's terms, in menu order, each built by term() under its key.
 * @param {{ definePrefix: string, chunk: string | null }} family
 * @param {Record<string, OwnTerm>} own
 * @returns {Record<string, TermEntry>}
 */
export const terms = (family, own) =>
  Object.fromEntries(Object.entries(own).map(([key, entry]) => [key, term(family, key, entry)]));
