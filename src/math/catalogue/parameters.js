// @ts-check
// The parameters several terms share, defined once: range, unit, label, the values the stress grids sweep and the
// uniform that carries each to the GPU (a parameter's kind, types.js, makes it a vec2 or an RGB colour uniform).
// A term names them in its params (and may narrow one, as SGD's α does); its own parameters (Blinn–Phong's
// exponent, ABC's a1, a2) stay in its entry. The JS functions (ndf.js's clampAlpha) and the GLSL (the generated
// chunk 'parameters.glsl': ALPHA_MIN, ALPHA_MAX) read the α range from here.

/** @typedef {import('./types.js').TermParam} TermParam */

/** The range of the microfacet roughness α every isotropic D and V term reads, and of each of αx, αy. */
const ALPHA_RANGE = {
  min: 1e-4,
  max: 1,
  unit: '',
  clamped: true,
  delicate: [1e-5, 1e-3, 0.01, 0.1, 0.3, 0.5],
};

/**
 * Largest roughness per axis the anisotropic functions take (src/math/anisotropic.js clamps each of αx, αy to
 * [α's min, this]): Burley's mapping reaches α/√0.1 ≈ 3.2 α and OpenPBR's √2 α.
 */
export const ALPHA_ANISO_MAX = 4;

/** @type {Record<string, TermParam>} */
export const PARAMETERS = {
  alpha: { ...ALPHA_RANGE, label: 'Roughness α', uniform: 'uAlpha' },
  // an anisotropic lobe's roughness along the tangent t and the bitangent b: the microfacet input's α pair
  alphaX: { ...ALPHA_RANGE, label: 'Roughness along the tangent αx' },
  alphaY: { ...ALPHA_RANGE, label: 'Roughness along the bitangent αy' },
  // the pair itself, as the hosts' programs read it (the microfacet input's alpha; isotropic terms read αx)
  alphaPair: {
    ...ALPHA_RANGE,
    max: ALPHA_ANISO_MAX,
    kind: 'vec2',
    label: 'Roughness pair (αx, αy)',
    uniform: 'uAlphaPair',
  },
  // the strength a of an anisotropic model (anisotropicAlphas maps α and a to the pair; the bent reflection reads a)
  anisotropy: { min: 0, max: 1, unit: '', label: 'Anisotropy a', clamped: true, uniform: 'uAnisotropy' },
  // the reflectance at normal incidence: Schlick's F0, the diffuse terms' and the compensations'
  f0: {
    min: 0,
    max: 1,
    unit: '',
    label: 'Reflectance at normal incidence F0',
    delicate: [0.02, 0.04, 0.17, 0.5, 0.95],
    uniform: 'uF0',
  },
  cdiff: { min: 0, max: 1, unit: '', label: 'Diffuse colour c_diff', clamped: true, uniform: 'uDiffuse' },
  sigma: {
    min: 0,
    max: Math.PI / 2,
    unit: 'rad',
    label: 'Roughness σ',
    delicate: [0.1, 0.3, 0.6, 1],
    uniform: 'uSigma',
  },
  E: { min: 0, max: 1, unit: '', label: 'Directional albedo E(n·v)' },
};

/** A number as a GLSL float literal. @param {number} x */
const glslFloat = (x) => (Number.isInteger(x) ? x.toFixed(1) : String(x));

/**
 * The generated chunk 'parameters.glsl': the ranges the GLSL clamps to, from the table.
 * @returns {string}
 */
export function parametersGlsl() {
  return [
    '// The shared parameters\u2019 ranges, generated from src/math/catalogue/parameters.js.',
    `#define ALPHA_MIN ${glslFloat(PARAMETERS.alpha.min)}`,
    `#define ALPHA_MAX ${glslFloat(PARAMETERS.alpha.max)}`,
  ].join('\n');
}
