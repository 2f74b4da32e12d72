// The BRDF lobe's state: the light and view (each at its own azimuth), BRDF A's terms and roughness, the factors
// switched on, the overlays (intensity, multiple scattering, BRDF B) and the φd of the (θh, θd) images. A's D, V
// and F, or A as a whole, can be the user's own GLSL (`custom`): its code and its sliders' values are fields too.
import { termOptions } from '../../math/catalogue/index.js';
import { SLOTS } from '../../core/custom/slots.js';
import { CONVENTION_LABELS } from '../ndf-explorer/words.js';
import { OPENPBR_LAYERS } from './openpbr-lobe.js';

const ndfOptions = termOptions('ndf');
const visOptions = termOptions('visibility');
const WITH_CUSTOM = { custom: true };

/** The code of A's user-written term in `slotKey` (no control of its own: the panel's editor edits it). */
/** A number of OpenPBR Surface's, under the specification's own name, in the OpenPBR folder. */
const OPENPBR_FOLDER = { group: 'OpenPBR Surface (A: model OpenPBR)', closed: true };
const openpbr = (label, fallback, min = 0) => ({
  ...OPENPBR_FOLDER,
  type: 'number',
  min,
  max: 1,
  step: 0.01,
  default: fallback,
  label,
});

const code = (slotKey, label) => ({ type: 'code', slot: slotKey, default: SLOTS[slotKey].starter, label });

export const schema = {
  lightTheta: { type: 'number', min: 0, max: 89, step: 1, default: 45, label: 'Light θl', unit: '°' },
  viewTheta: { type: 'number', min: -89, max: 89, step: 1, default: 45, label: 'View θv (+: mirror side)', unit: '°' },
  brdf: {
    type: 'enum',
    options: {
      microfacet: 'Microfacet F·D·V/4',
      custom: 'Custom whole BRDF (your GLSL)',
      openpbr: 'OpenPBR Surface',
    },
    default: 'microfacet',
    label: 'BRDF A: model',
  },
  D: { type: 'enum', options: termOptions('ndf', undefined, WITH_CUSTOM), default: 'ggx', label: 'A: distribution D' },
  V: {
    type: 'enum',
    options: termOptions('visibility', undefined, WITH_CUSTOM),
    default: 'smithGGXCorrelated',
    label: 'A: visibility V',
  },
  // a custom F is A's (B keeps Schlick)
  F: {
    type: 'enum',
    options: termOptions('fresnel', ['schlick', 'one'], WITH_CUSTOM),
    default: 'schlick',
    label: 'Fresnel F',
  },
  alpha: { type: 'number', min: 0.02, max: 1, step: 0.01, default: 0.3, label: 'A: roughness α' },
  f0: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.04, label: 'F0' },
  useF: { type: 'bool', default: true, label: 'Use F (Fresnel)' },
  useD: { type: 'bool', default: true, label: 'Use D (distribution)' },
  useG: { type: 'bool', default: true, label: 'Use G (shadowing)' },
  useDenominator: { type: 'bool', default: true, label: 'Divide by 4(n·l)(n·v)' },
  cosine: { type: 'bool', default: false, label: 'Lobe × n·v (intensity)' },
  multiple: { type: 'bool', default: false, label: 'Add multiple bounces (A)' },
  compare: { type: 'bool', default: false, label: 'Compare with BRDF B' },
  D2: { type: 'enum', options: ndfOptions, default: 'beckmann', label: 'B: distribution D' },
  V2: { type: 'enum', options: visOptions, default: 'smithBeckmannSeparable', label: 'B: visibility V' },
  alpha2: { type: 'number', min: 0.02, max: 1, step: 0.01, default: 0.3, label: 'B: roughness α' },
  phiD: { type: 'number', min: 0, max: 180, step: 1, default: 90, label: 'φd of the images', unit: '°' },
  codeD: code('D', 'A: your D (GLSL)'),
  codeV: code('V', 'A: your V (GLSL)'),
  codeF: code('F', 'A: your F (GLSL)'),
  codeBRDF: code('brdf', 'A: your BRDF (GLSL)'),
  params: { type: 'params', default: {}, label: 'Sliders of your code' },
  // beyond the talk (issue 28): the light's azimuth from the tangent (the plane of incidence goes through it), the
  // view's own azimuth off that plane (azimuths.js), and A's GGX or Beckmann stretched along the tangent. An old
  // link's `phi` (the plane's azimuth, the light opposite it) reads as φl: the old scene turned by 180° about n,
  // whose values no term here tells apart (an anisotropic D and Λ read cos²φ and sin²φ only).
  lightPhi: {
    type: 'number',
    min: 0,
    max: 360,
    step: 1,
    default: 180,
    label: 'Light azimuth φl from t',
    unit: '°',
    formerly: ['phi'],
  },
  viewPhi: {
    type: 'number',
    min: -180,
    max: 180,
    step: 1,
    default: 0,
    label: 'View azimuth Δφ off the plane of incidence',
    unit: '°',
  },
  anisotropy: { type: 'number', min: 0, max: 1, step: 0.01, default: 0, label: 'A: anisotropy (GGX, Beckmann)' },
  convention: {
    type: 'enum',
    options: CONVENTION_LABELS,
    default: 'burley2012',
    label: 'A: anisotropy convention',
  },
  // beyond the talk (issue 29): A as OpenPBR Surface's layered material, a few of its parameters by its own names
  // (the roughnesses from 0.1: a mirror-like layer's lobe is narrower than the plot's half-degree steps)
  base_color: { ...OPENPBR_FOLDER, type: 'color', default: '#e7e7e7', label: 'base_color (sRGB)' },
  base_metalness: openpbr('base_metalness', 0),
  specular_color: { ...OPENPBR_FOLDER, type: 'color', default: '#ffffff', label: 'specular_color (sRGB)' },
  specular_roughness: openpbr('specular_roughness', 0.3, 0.1),
  coat_weight: openpbr('coat_weight', 0),
  coat_roughness: openpbr('coat_roughness', 0.1, 0.1),
  fuzz_weight: openpbr('fuzz_weight', 0),
  fuzz_roughness: openpbr('fuzz_roughness', 0.5, 0.1),
  openpbrLayer: {
    ...OPENPBR_FOLDER,
    type: 'enum',
    options: { none: 'none', ...Object.fromEntries(Object.entries(OPENPBR_LAYERS).map(([k, x]) => [k, x.short])) },
    default: 'coat',
    label: '3-D wireframe: one layer’s part',
  },
  openpbrParts: { ...OPENPBR_FOLDER, type: 'bool', default: true, label: 'Show each layer’s part' },
};
