// @ts-check
// The material lab's anisotropic lobe (issue 28), decided in one place: the roughness pair (αx, αy) from the
// state's α and anisotropy by the chosen model's mapping (anisotropicAlphas of src/math/anisotropic.js), the
// tangent field on the sphere the pair is laid along (shaders/lab-tangent.glsl), and which terms the lab stretches:
// the chosen D and V in their catalogue's anisotropic forms (anisotropic-forms.js: GGX's and Beckmann's D, the
// height-correlated Smith V, Heitz 2014), or the user's customDAniso and customVAniso. The reference and importance
// sampling draw the visible normals of GGX stretched by the pair (Dupuy & Benyoub 2023, the one anisotropic sampler
// of shaders/anisotropic.glsl) for every D. Pure: loads in Node.
import { anisotropicAlphas } from '../math/anisotropic.js';
import { DEG, lightDirFromAngles } from '../math/angles.js';
import { anisotropicForm } from '../math/catalogue/anisotropic-forms.js';
import { termCall } from '../core/gpu/term-chunks.js';
import { CUSTOM_KEY, termEntry } from '../math/catalogue/index.js';
import { SLOTS } from '../core/custom/slots.js';

/** The mappings from (α, a) to (αx, αy), as anisotropicAlphas names them. */
export const ANISOTROPY_MODELS = {
  burley2012: 'Burley 2012 (Disney): aspect √(1 − 0.9a)',
  gltf: 'glTF KHR_materials_anisotropy',
  openpbr: 'OpenPBR Surface 1.1',
};

/** The tangent fields: the brushing's lines run along b; the lobe's larger roughness αx is across them, along t. */
export const TANGENT_FIELDS = {
  around: 'Brushed around a pole (a machined disc)',
  along: 'Brushed along an axis (a brushed plate)',
};

/** Where the stretched D and V come from: the chosen term's form in the catalogue, or the user's GLSL. */
export const ANISOTROPIC_TERMS = {
  D: { chosen: 'The D above, stretched', custom: 'Yours: customDAniso' },
  V: { chosen: 'The V above, stretched', custom: 'Yours: customVAniso' },
};

/** The anisotropic lobe whose visible normals the reference and importance sampling draw, for every D. */
export const SAMPLED_LOBE = 'ggxAniso';

/**
 * @typedef {object} TangentField
 * @property {'around' | 'along'} mode  circles around the axis, or lines along it
 * @property {number[]} axis  unit, view space (z towards the viewer, y up)
 * @property {number} rotation  of (t, b) about n, radians
 */

/**
 * @typedef {object} LabAnisotropy
 * @property {number} strength  the anisotropy a in (0, 1]
 * @property {string} model  a key of ANISOTROPY_MODELS
 * @property {number[]} alpha  [αx, αy]
 * @property {TangentField} field
 * @property {boolean} bent  the approximations read the bent reflection vector (else the mirror direction)
 * @property {string | null} D  the stretched D: a catalogue key, 'custom' (customDAniso), or null (none: the lobe
 *   stays isotropic)
 * @property {string | null} V  the stretched V, as D; null: the chosen V at α
 */

/**
 * The tangent field of a lab state (drawn even while the anisotropy is 0, to be set before it is raised).
 * @param {{ tangentField?: string, tangentTheta?: number, tangentPhi?: number, tangentRotation?: number }} state
 * @returns {TangentField}
 */
export const tangentFieldOf = (state) => ({
  mode: state.tangentField === 'along' ? 'along' : 'around',
  axis: lightDirFromAngles(state.tangentTheta ?? 0, state.tangentPhi ?? 0),
  rotation: (state.tangentRotation ?? 0) * DEG,
});

/**
 * The key of the stretched term of a family: the user's ('custom') when the state asks for it, else the catalogue's
 * form of the chosen term, or null.
 * @param {'ndf' | 'visibility'} family
 * @param {string | undefined} chosen  the state's isotropic choice
 * @param {string | undefined} source  a key of ANISOTROPIC_TERMS.D or .V
 */
const stretchedKey = (family, chosen, source) =>
  source === CUSTOM_KEY ? CUSTOM_KEY : (anisotropicForm(family, chosen ?? '')?.key ?? null);

/**
 * The anisotropic lobe of a lab state, or null when its anisotropy is 0 (or the state has none: the lab's other
 * widgets).
 * @param {{ alpha: number, anisotropy?: number, anisotropyModel?: string, tangentField?: string,
 *   tangentTheta?: number, tangentPhi?: number, tangentRotation?: number, bentReflection?: boolean, D?: string,
 *   V?: string, anisoD?: string, anisoV?: string }} state
 * @returns {LabAnisotropy | null}
 */
export function anisotropyOf(state) {
  const strength = state.anisotropy ?? 0;
  if (!(strength > 0)) return null;
  const model = state.anisotropyModel ?? 'burley2012';
  return {
    strength,
    model,
    alpha: anisotropicAlphas(state.alpha, strength, model),
    field: tangentFieldOf(state),
    bent: state.bentReflection ?? true,
    D: stretchedKey('ndf', state.D, state.anisoD),
    V: stretchedKey('visibility', state.V, state.anisoV),
  };
}

/**
 * Whether the lab draws `scene`'s specular lobe anisotropic: an anisotropy is set, the BRDF is the model's (not a
 * table or the user's whole BRDF), its D has a stretched form (the catalogue's or the user's) and its specular
 * layer is on.
 * @param {{ anisotropy?: LabAnisotropy | null, terms: { D: string, layers: string }, measured?: string,
 *   custom?: object }} scene
 */
export const stretchesLobe = (scene) =>
  Boolean(scene.anisotropy?.D) && !scene.measured && !scene.custom && scene.terms.layers !== 'diffuse';

/** The user's slots the lab's stretched lobe draws (customDAniso, customVAniso), for `anisotropy`. */
export const ownSlots = (/** @type {LabAnisotropy | null | undefined} */ anisotropy) =>
  /** @type {('DAniso' | 'VAniso')[]} */ (
    [
      ['DAniso', anisotropy?.D],
      ['VAniso', anisotropy?.V],
    ]
      .filter(([, key]) => key === CUSTOM_KEY)
      .map(([slot]) => slot)
  );

/** A stretched term's call over the microfacet input m (shaders/microfacet-input.glsl). */
const callOf = (/** @type {'ndf' | 'visibility'} */ family, /** @type {string} */ key) => {
  if (key === CUSTOM_KEY) return SLOTS[family === 'ndf' ? 'DAniso' : 'VAniso'].call;
  const entry = termEntry(family, key);
  // shaders/lab-anisotropy.glsl includes the anisotropic terms' one chunk; a term elsewhere would not compile
  if (entry.chunk !== 'anisotropic.glsl') throw new Error(`lab: ${key}'s chunk ${entry.chunk} is not included`);
  return termCall(entry);
};

/**
 * The #defines of the stretched lobe of `scene` (when stretchesLobe): ANISOTROPIC, the calls of its D and V
 * (ANISOTROPIC_D, ANISOTROPIC_V: GLSL over the microfacet input, read by shaders/lab-anisotropy.glsl) and, for the
 * user's, the switch that includes their chunk; the tangent field's and the bent reflection's switches.
 * @param {{ anisotropy: LabAnisotropy }} scene
 * @param {boolean} reference
 * @returns {Record<string, 1 | string>}
 */
export function anisotropicDefines({ anisotropy: a }, reference) {
  /** @type {Record<string, 1 | string>} */
  const d = { ANISOTROPIC: 1, ANISOTROPIC_D: callOf('ndf', /** @type {string} */ (a.D)) };
  if (a.V) d.ANISOTROPIC_V = callOf('visibility', a.V);
  for (const slot of ownSlots(a)) d[`CUSTOM_${slot.toUpperCase()}`] = 1;
  if (a.field.mode === 'along') d.TANGENT_ALONG = 1;
  if (a.bent && !reference) d.BENT_REFLECTION = 1;
  return d;
}
