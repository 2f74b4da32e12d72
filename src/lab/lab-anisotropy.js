// @ts-check
// The material lab's anisotropic lobe (issue 28), decided in one place: the roughness pair (αx, αy) from the
// state's α and anisotropy by the chosen model's mapping (anisotropicAlphas of src/math/anisotropic.js), the
// tangent field on the sphere the pair is laid along (shaders/lab-tangent.glsl), and which chosen terms the lab
// stretches: GGX, the one D with an anisotropic visible-normal sampler (Dupuy & Benyoub 2023) for the reference
// and importance sampling, with the height-correlated Smith V in its anisotropic form (Heitz 2014). Pure: loads
// in Node.
import { anisotropicAlphas } from '../math/anisotropic.js';
import { DEG, lightDirFromAngles } from '../math/angles.js';

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

/** The D the lab stretches, and the V it has an anisotropic form of (any other V keeps its isotropic form at α). */
export const ANISOTROPIC_D = 'ggx';
export const ANISOTROPIC_V = 'smithGGXCorrelated';

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
 * The anisotropic lobe of a lab state, or null when its anisotropy is 0 (or the state has none: the lab's other
 * widgets).
 * @param {{ alpha: number, anisotropy?: number, anisotropyModel?: string, tangentField?: string,
 *   tangentTheta?: number, tangentPhi?: number, tangentRotation?: number, bentReflection?: boolean }} state
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
  };
}

/**
 * Whether the lab draws `scene`'s specular lobe anisotropic: an anisotropy is set, the BRDF is the model's (not a
 * table or the user's), its D is GGX and its specular layer is on.
 * @param {{ anisotropy?: LabAnisotropy | null, terms: { D: string, layers: string }, measured?: string,
 *   custom?: object }} scene
 */
export const stretchesLobe = (scene) =>
  Boolean(scene.anisotropy) &&
  !scene.measured &&
  !scene.custom &&
  scene.terms.D === ANISOTROPIC_D &&
  scene.terms.layers !== 'diffuse';
