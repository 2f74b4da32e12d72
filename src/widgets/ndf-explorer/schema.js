// The NDF explorer's state: the matched half width, the shapes of ABC and SGD, which NDFs are drawn, the
// spheres' light and exposure, the measured slice the measured-BRDF widget hands over, and the user's own D (its
// code and its sliders' values), drawn when `custom` is among the NDFs (`D`, the catalogue's name for the choice).
import { termOptions } from '../../math/catalogue/index.js';
import { SLOTS } from '../../core/custom/slots.js';
import { CONVENTION_LABELS } from './words.js';

/** The talk's five NDFs (catalogue keys), in the order the talk shows them: menu, legend and colour order. */
export const NDF_KEYS = ['blinnPhong', 'beckmann', 'ggx', 'abc', 'sgd'];

export const schema = {
  hwhm: { type: 'number', min: 1, max: 40, step: 0.5, default: 8, label: 'Matched half width', unit: '°' },
  abcA2: { type: 'number', min: 0.5, max: 10, step: 0.1, default: 2.5, label: 'ABC shape a2' },
  sgdP: { type: 'number', min: 0, max: 1.9, step: 0.01, default: 0.64, label: 'SGD shape p' },
  D: {
    type: 'set',
    formerly: ['ndfs'],
    options: termOptions('ndf', NDF_KEYS, { custom: true }),
    default: NDF_KEYS,
    label: 'Distributions',
  },
  lightTheta: { type: 'number', min: 0, max: 80, step: 1, default: 35, label: 'Light from view', unit: '°' },
  exposure: { type: 'number', min: 0.05, max: 50, step: 0.05, default: 1, label: 'Exposure' },
  // the NDF a measurement implies, as the measured-BRDF widget hands it over: D/D(0) at the 90 θh nodes of a
  // MERL table (0: missing or below 1e-5), and the name of its file
  measured: { type: 'samples', length: 90, min: 0, max: 1, default: [], label: 'Measured NDF slice' },
  measuredName: { type: 'text', maxLength: 80, default: '', label: 'Measured file' },
  codeD: { type: 'code', slot: 'D', default: SLOTS.D.starter, label: 'Your D (GLSL)' },
  params: { type: 'params', default: {}, label: 'Sliders of your code' },
  // beyond the talk (issue 28): GGX and Beckmann stretched along the tangent, (α, anisotropy) → (αx, αy) by one
  // of three published conventions
  anisotropy: { type: 'number', min: 0, max: 1, step: 0.01, default: 0, label: 'Anisotropy (GGX, Beckmann)' },
  convention: {
    type: 'enum',
    options: CONVENTION_LABELS,
    default: 'burley2012',
    label: 'Anisotropy convention',
  },
};
