// @ts-check
// The user-written term of a family (issue 13): a menu's `custom` option. It has no float64 function (the user's
// code only ever runs as GLSL: src/core/custom/gpu-eval.js evaluates it for curves and checks); in GLSL it is the
// user's function in the chunk 'custom-<slot>.glsl' (src/core/custom/assemble.js writes it), picked by
// `<PREFIX>_CUSTOM` in the family's generated dispatch (src/core/gpu/term-chunks.js). Not in a family's `terms`:
// menus offer it only when asked (termOptions(family, keys, { custom: true })), as a widget must bring the code.

import { FIELDS } from './microfacet-input.js';

export const CUSTOM_KEY = 'custom';

/**
 * @param {string} definePrefix
 * @param {string} slot the slot's key in src/core/custom/slots.js
 * @param {string} glsl the user's function
 * @param {string | null} glslCall its call over the family dispatch's arguments; null: its function over args, the
 *   microfacet input's fields (a D or V slot: the user's signature stays, the dispatch passes it m's fields)
 * @param {string[]} args
 * @returns {import('./types.js').TermEntry}
 */
const custom = (definePrefix, slot, glsl, glslCall, args) => ({
  key: CUSTOM_KEY,
  label: 'Custom (your GLSL)',
  short: 'Custom',
  cite: 'your own code',
  js: null,
  evaluate: null,
  glsl,
  chunk: `custom-${slot}.glsl`,
  define: `${definePrefix}_CUSTOM`,
  glslCall: glslCall ?? `${glsl}(${args.map((arg) => FIELDS[arg].glsl).join(', ')})`,
  args,
  params: {},
});

/**
 * The custom term of each family that offers one. The diffuse dispatch is shaders/diffuse-term.glsl, written by
 * hand: its DIFFUSE_CUSTOM branch calls customDiffuse with σ as its α; the others' dispatch is generated.
 * @type {Partial<Record<import('./types.js').FamilyName, import('./types.js').TermEntry>>}
 */
export const CUSTOM_TERMS = {
  ndf: custom('NDF', 'D', 'customD', null, ['nh', 'alpha']),
  visibility: custom('VIS', 'V', 'customV', null, ['nl', 'nv', 'alpha']),
  fresnel: custom('F', 'F', 'customF', 'customF(f0, lh)', ['f0', 'lh']),
  diffuse: custom('DIFFUSE', 'diffuse', 'customDiffuse', 'customDiffuse(cdiff, l, v, alpha)', [
    'cdiff',
    'l',
    'v',
    'alpha',
  ]),
};
