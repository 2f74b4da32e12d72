// The material lab's state: the material, the BRDF's terms, four lights with the method each is shaded by, the
// reference and the display. All of it round-trips through the URL; a dropped file cannot, so the state says
// only that a file is in use. The BRDF may be the user's own GLSL: its code and its sliders' values are fields too.
// Pure data: loads in Node without three.js.
import { ENVIRONMENTS } from '../../lab/environments.js';
import { MATERIAL_FIELDS } from '../../lab/lab-scene.js';
import { LAB_TERMS } from '../../lab/lab-approximations.js';
import { TERM_ALIASES } from '../../math/catalogue/index.js';
import { SIGMA_HINT } from '../../core/ui/sigma-range.js';
import { SLOTS } from '../../core/custom/slots.js';

export const ENV_METHODS = {
  'split-sum': 'Split sum (prefiltered + DFG)',
  importance: 'Importance sampling, N samples',
  mirror: 'Mirror: F(v, n) × environment',
  pmrem: 'three.js PMREM (MeshPhysicalMaterial)',
};
export const AREA_METHODS = { representative: 'Representative point (Karis)', centre: 'Punctual at the centre' };

export const schema = {
  ...MATERIAL_FIELDS,
  layers: {
    group: 'BRDF terms',
    type: 'enum',
    options: { both: 'Specular + diffuse', specular: 'Specular only', diffuse: 'Diffuse only' },
    default: 'both',
    label: 'Layers',
  },
  // the terms under the catalogue's names for a choice (F, D, V, diffuse, compensation); `formerly`: old links' names
  F: {
    group: 'BRDF terms',
    type: 'enum',
    formerly: ['fresnel'],
    options: LAB_TERMS.fresnel,
    default: 'schlick',
    label: 'Fresnel F',
  },
  D: {
    group: 'BRDF terms',
    type: 'enum',
    formerly: ['ndf'],
    options: LAB_TERMS.ndf,
    default: 'ggx',
    label: 'Distribution D',
  },
  V: {
    group: 'BRDF terms',
    type: 'enum',
    formerly: ['visibility'],
    options: LAB_TERMS.visibility,
    default: 'smithGGXCorrelated',
    label: 'Visibility V',
  },
  compensation: {
    group: 'BRDF terms',
    type: 'enum',
    options: LAB_TERMS.compensation,
    default: 'none',
    label: 'Multiple scattering',
  },
  diffuse: {
    group: 'BRDF terms',
    type: 'enum',
    formerly: ['diffuseModel'], // and `diffuse` was the colour, now `cdiff`: the value tells which is meant
    options: LAB_TERMS.diffuse,
    aliases: TERM_ALIASES.diffuse, // the spellings of old links: 'oren-nayar', …
    default: 'lambert',
    label: 'Diffuse term',
  },
  sigma: {
    group: 'BRDF terms',
    type: 'number',
    min: 0,
    max: 60,
    step: 1,
    default: 20,
    label: 'Oren-Nayar σ',
    unit: '°',
    hint: SIGMA_HINT,
  },
  brdfSource: {
    group: 'BRDF terms',
    type: 'enum',
    default: 'model',
    label: 'BRDF',
    options: {
      model: 'The model (terms above)',
      measured: 'Measured (a dropped MERL file)',
      custom: 'Your GLSL: a whole BRDF f(l, v)',
    },
  },
  // the user's whole BRDF (no control of its own: the panel's editor edits it) and its sliders' values
  codeBRDF: { type: 'code', slot: 'brdf', default: SLOTS.brdf.starter, label: 'Your BRDF (GLSL)' },
  params: { type: 'params', default: {}, label: 'Sliders of your code' },
  // on by default: the talk's first light, exact in both images (L = π f c_light (n·l)); the readout reads it
  punctual: { group: 'Punctual light', type: 'bool', default: true, label: 'Punctual light' },
  lightTheta: {
    group: 'Punctual light',
    type: 'number',
    min: 0,
    max: 180,
    step: 1,
    default: 45,
    label: 'Punctual θ from view',
    unit: '°',
  },
  lightPhi: {
    group: 'Punctual light',
    type: 'number',
    min: -180,
    max: 180,
    step: 1,
    default: 45,
    label: 'Punctual φ',
    unit: '°',
  },
  cLight: {
    group: 'Punctual light',
    type: 'number',
    min: 0,
    max: 10,
    step: 0.05,
    default: 1,
    label: 'Punctual c_light',
  },
  // the folders of the lights that start off, and of the display, start closed: the panel stays near the view's height
  area: { group: 'Sphere light', closed: true, type: 'bool', default: false, label: 'Sphere light' },
  areaTheta: {
    group: 'Sphere light',
    type: 'number',
    min: 0,
    max: 180,
    step: 1,
    default: 40,
    label: 'Sphere light θ',
    unit: '°',
  },
  areaPhi: {
    group: 'Sphere light',
    type: 'number',
    min: -180,
    max: 180,
    step: 1,
    default: 135,
    label: 'Sphere light φ',
    unit: '°',
  },
  areaRadius: {
    group: 'Sphere light',
    type: 'number',
    min: 0.5,
    max: 30,
    step: 0.5,
    default: 8,
    label: 'Sphere light radius',
    unit: '°',
  },
  areaCLight: {
    group: 'Sphere light',
    type: 'number',
    min: 0,
    max: 10,
    step: 0.05,
    default: 1,
    label: 'Sphere light c_light',
  },
  areaMethod: {
    group: 'Sphere light',
    type: 'enum',
    options: AREA_METHODS,
    default: 'representative',
    label: 'Sphere light by',
  },
  env: { group: 'Environment', type: 'bool', default: true, label: 'Environment' },
  environment: {
    group: 'Environment',
    type: 'enum',
    options: ENVIRONMENTS,
    default: 'studio',
    label: 'Environment map',
  },
  envIntensity: {
    group: 'Environment',
    type: 'number',
    min: 0,
    max: 4,
    step: 0.05,
    default: 1,
    label: 'Environment intensity',
  },
  envMethod: {
    group: 'Environment',
    type: 'enum',
    options: ENV_METHODS,
    default: 'split-sum',
    label: 'Environment by',
  },
  samples: {
    group: 'Environment',
    type: 'number',
    min: 1,
    max: 256,
    step: 1,
    default: 16,
    label: 'Importance samples N',
  },
  ambient: { group: 'Ambient light', closed: true, type: 'bool', default: false, label: 'Ambient light' },
  ambientLevel: {
    group: 'Ambient light',
    type: 'number',
    min: 0,
    max: 2,
    step: 0.05,
    default: 0.3,
    label: 'Ambient radiance',
  },
  refSamples: {
    group: 'Reference and display',
    closed: true,
    type: 'enum',
    options: { 128: '128', 512: '512', 2048: '2048' },
    default: '512',
    label: 'Reference samples / pixel',
  },
  exposure: {
    group: 'Reference and display',
    type: 'number',
    min: 0.1,
    max: 8,
    step: 0.05,
    default: 1,
    label: 'Exposure',
  },
  errorScale: {
    group: 'Reference and display',
    type: 'number',
    min: 0.005,
    max: 1,
    step: 0.005,
    default: 0.05,
    label: 'Error image: full scale',
  },
};
