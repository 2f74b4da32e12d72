// The visibility explorer's state: the roughness, how l and v move for the plots, which terms are drawn, and
// the spheres' light and exposure, and the user's own V (its code and its sliders' values), drawn when `custom` is
// among the terms.
import { termOptions } from '../../math/catalogue/index.js';
import { SLOTS } from '../../core/custom/slots.js';
import { CONVENTION_LABELS } from '../ndf-explorer/words.js';

export const schema = {
  // rough by default: the terms part most there (on the spheres too), and the smooth end is one drag away
  alpha: { type: 'number', min: 0.01, max: 1, step: 0.01, default: 0.8, label: 'Roughness α' },
  config: {
    type: 'enum',
    options: { mirror: 'l, v mirrored about n (h = n)', 'view-fixed': 'View fixed, light sweeps' },
    default: 'view-fixed',
    label: 'Directions',
  },
  viewTheta: { type: 'number', min: 0, max: 85, step: 1, default: 60, label: 'View angle (view fixed)', unit: '°' },
  V: {
    type: 'set',
    formerly: ['terms'],
    options: termOptions('visibility', undefined, { custom: true }),
    default: [
      'implicit',
      'cookTorrance',
      'kelemen',
      'smithGGXSeparable',
      'smithGGXCorrelated',
      'smithGGXCorrelatedFast',
      'schlickGGX',
    ],
    label: 'Terms',
  },
  // a light near grazing and no clipping by default: V matters where the light is low, and the spheres differ there
  lightTheta: { type: 'number', min: 0, max: 85, step: 1, default: 75, label: 'Sphere light from view', unit: '°' },
  exposure: { type: 'number', min: 0.1, max: 20, step: 0.1, default: 1, label: 'Sphere exposure' },
  codeV: { type: 'code', slot: 'V', default: SLOTS.V.starter, label: 'Your V (GLSL)' },
  params: { type: 'params', default: {}, label: 'Sliders of your code' },
  // beyond the talk (issue 28): the azimuth plot's surface, α stretched along the tangent by one convention
  anisotropy: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.6, label: 'Anisotropy (azimuth plot)' },
  convention: {
    type: 'enum',
    options: CONVENTION_LABELS,
    default: 'burley2012',
    label: 'Anisotropy convention',
  },
};
