// The visibility explorer's state: the roughness, how l and v move for the plots, which terms are drawn, and
// the spheres' light and exposure.
import { termOptions } from '../../math/catalogue/index.js';

export const schema = {
  alpha: { type: 'number', min: 0.01, max: 1, step: 0.01, default: 0.5, label: 'Roughness α' },
  config: {
    type: 'enum',
    options: { mirror: 'l, v mirrored about n (h = n)', 'view-fixed': 'View fixed, light sweeps' },
    default: 'view-fixed',
    label: 'Directions',
  },
  viewTheta: { type: 'number', min: 0, max: 85, step: 1, default: 60, label: 'View angle (view fixed)', unit: '°' },
  terms: {
    type: 'set',
    options: termOptions('visibility'),
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
  lightTheta: { type: 'number', min: 0, max: 85, step: 1, default: 30, label: 'Sphere light from view', unit: '°' },
  exposure: { type: 'number', min: 0.1, max: 20, step: 0.1, default: 1.5, label: 'Sphere exposure' },
};
