// The measured-BRDF widget's state (all of it round-trips through the URL; a dropped file cannot, so the
// state names the synthetic example shown until one is dropped).
import { FIT_MODELS } from '../../measured/fit.js';
import { EXAMPLES } from './model.js';

export const TERMS_USED = [
  'fresnelSchlick',
  'ndfGGX',
  'ndfBeckmann',
  'ndfBlinnPhong',
  'ndfABC',
  'ndfSGD',
  'visibilitySmithGGXCorrelated',
  'visibilitySmithBeckmannSeparable',
  'visibilityCookTorrance',
  'merlCoordinates',
];

export const schema = {
  example: {
    type: 'enum',
    options: Object.fromEntries(Object.entries(EXAMPLES).map(([k, e]) => [k, `Synthetic ${e.model.toUpperCase()}`])),
    default: 'ggx',
    label: 'Example (synthetic)',
  },
  lightTheta: { type: 'number', min: 0, max: 85, step: 1, default: 30, label: 'Lobe: light θl', unit: '°' },
  overlay: {
    type: 'enum',
    options: Object.fromEntries(Object.entries(FIT_MODELS).map(([k, m]) => [k, m.label])),
    default: 'ggx',
    label: 'Overlaid fit',
  },
  phiD: { type: 'number', min: 0, max: 179, step: 1, default: 90, label: 'Images φd', unit: '°' },
  sphereLight: { type: 'number', min: 0, max: 80, step: 1, default: 35, label: 'Spheres: light from view', unit: '°' },
  exposure: { type: 'number', min: 0.05, max: 20, step: 0.05, default: 1, label: 'Spheres: exposure' },
};
