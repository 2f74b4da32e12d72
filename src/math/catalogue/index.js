// @ts-check
// One catalogue of the BRDF's terms, by family: each term's key (its one spelling in state and URLs), its one
// label, its source, its float64 function, its GLSL function and the #define that selects it. Menus, URL enums,
// shader variants, graders, parity rows, stress domains and bench families derive from it; adding a term is its
// JS function, its GLSL function and one entry in its family's module (tests/unit/add-a-term.test.js).
import { COMPENSATION_FAMILY } from './compensation-terms.js';
import { CUSTOM_KEY, CUSTOM_TERMS } from './custom-terms.js';
import { DIFFUSE_FAMILY } from './diffuse-terms.js';
import { FRESNEL_FAMILY } from './fresnel-terms.js';
import { NDF_FAMILY } from './ndf-terms.js';
import { VISIBILITY_FAMILY } from './visibility-terms.js';

/** @typedef {import('./types.js').FamilyName} FamilyName */
/** @typedef {import('./types.js').TermEntry} TermEntry */
/** @typedef {import('./types.js').TermFamily} TermFamily */

/**
 * A choice of terms, by the keys of the microfacet BRDF's params ({ F, D, V }) and the lab's
 * ({ diffuse, compensation }). Each is optional.
 * @typedef {{ F?: string, D?: string, V?: string, diffuse?: string, compensation?: string }} TermChoice
 */

/** @type {Record<FamilyName, TermFamily>} */
export const CATALOGUE = {
  fresnel: FRESNEL_FAMILY,
  ndf: NDF_FAMILY,
  visibility: VISIBILITY_FAMILY,
  diffuse: DIFFUSE_FAMILY,
  compensation: COMPENSATION_FAMILY,
};

/**
 * Old URL spellings still accepted, family → { old: key } (the material lab's kebab-case diffuse models);
 * coerceState reads them through a schema field's `aliases`.
 * @type {Partial<Record<FamilyName, Record<string, string>>>}
 */
export const TERM_ALIASES = {
  diffuse: {
    'fresnel-weighted': 'fresnelWeighted',
    'ashikhmin-shirley': 'ashikhminShirley',
    'oren-nayar': 'orenNayar',
    'oren-nayar-qualitative': 'orenNayarQualitative',
  },
};

/**
 * The family's entry for key (an old spelling of TERM_ALIASES accepted; 'custom', the user-written term, in a family
 * with a slot); throws for a key it does not hold.
 * @param {FamilyName} family
 * @param {string} key
 * @returns {TermEntry}
 */
export function termEntry(family, key) {
  const terms = CATALOGUE[family]?.terms;
  if (!terms) throw new Error(`catalogue: no family '${family}'`);
  if (key === CUSTOM_KEY && CUSTOM_TERMS[family]) return CUSTOM_TERMS[family];
  const alias = TERM_ALIASES[family]?.[key];
  const entry = terms[key] ?? (alias ? terms[alias] : undefined);
  if (!entry) throw new Error(`catalogue: no ${family} term '${key}'`);
  return entry;
}

/**
 * The one label of a term.
 * @param {FamilyName} family
 * @param {string} key
 */
export const termLabel = (family, key) => termEntry(family, key).label;

/**
 * The keys a family's menus offer by default: every term, but in a D or V family those without a function of the
 * cosines (`evaluate`: the curves and the JS BRDF read it), such as an anisotropic lobe that reads the whole
 * microfacet input, which no widget has the controls for (it stays in the catalogue: dispatch, parity, stress).
 * @param {FamilyName} family
 */
const menuKeys = (family) =>
  Object.values(CATALOGUE[family].terms)
    .filter((term) => term.evaluate || !CATALOGUE[family].microfacetInput)
    .map((term) => term.key);

/**
 * { key: label } of a family, in menu order (menuKeys), or of the given keys in their order (for enum and set
 * options); `custom: true` adds the user-written term last, in a family that has one (see CUSTOM_TERMS).
 * @param {FamilyName} family
 * @param {string[]} [keys]
 * @param {{ custom?: boolean }} [options]
 * @returns {Record<string, string>}
 */
export function termOptions(family, keys = menuKeys(family), { custom = false } = {}) {
  const withCustom = custom && CUSTOM_TERMS[family] ? [...keys, CUSTOM_KEY] : keys;
  return Object.fromEntries(withCustom.map((key) => [key, termLabel(family, key)]));
}

export { CUSTOM_KEY, CUSTOM_TERMS };

/** @type {Record<string, FamilyName>} */
const FAMILY_OF_CHOICE = Object.fromEntries(Object.values(CATALOGUE).map((f) => [f.choice, f.family]));

/**
 * The #defines that select a choice of terms in GLSL, for the families given only: { NDF_GGX: true, … }.
 * A term without a define is the absence of a switch where the family has no dispatch (no compensation); where
 * it has one, no shader can draw the term, and this throws.
 * @param {TermChoice} choice
 * @returns {Record<string, true>}
 */
export function termDefines(choice) {
  /** @type {Record<string, true>} */
  const defines = {};
  for (const [slot, key] of Object.entries(choice)) {
    if (key === undefined) continue;
    const family = FAMILY_OF_CHOICE[slot];
    if (!family) throw new Error(`catalogue: '${slot}' is no term family (F, D, V, diffuse, compensation)`);
    const { define } = termEntry(family, key);
    if (define) defines[define] = true;
    else if (CATALOGUE[family].glslDispatch) throw new Error(`catalogue: no GLSL dispatch offers ${family} '${key}'`);
  }
  return defines;
}
