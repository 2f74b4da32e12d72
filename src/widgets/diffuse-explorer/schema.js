// The diffuse explorer's state: which models are drawn, their parameters (σ, c_diff, the specular F0 of the
// trade-off), the light of the spheres and the profile, the view of the sweep plot, the spheres' exposure, and
// the user's own diffuse term (its code and its sliders' values), drawn when `custom` is among the models.
import { SIGMA_HINT } from '../../core/ui/sigma-range.js';
import { termOptions } from '../../math/catalogue/index.js';
import { SLOTS } from '../../core/custom/slots.js';

export const schema = {
  diffuse: {
    type: 'set',
    formerly: ['models'],
    options: termOptions('diffuse', undefined, { custom: true }),
    default: Object.keys(termOptions('diffuse')),
    label: 'Diffuse models',
  },
  sigma: {
    type: 'number',
    min: 0,
    max: 90,
    step: 1,
    default: 40,
    label: 'Oren–Nayar roughness σ',
    unit: '°',
    hint: SIGMA_HINT,
  },
  cdiff: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.8, label: 'Diffuse colour c_diff' },
  f0: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.04, label: 'Specular F0 (trade-off)' },
  lightTheta: { type: 'number', min: 0, max: 180, step: 0.5, default: 0, label: 'Light from view', unit: '°' },
  lightPhi: { type: 'number', min: -180, max: 180, step: 0.5, default: 0, label: 'Light around view', unit: '°' },
  viewTheta: { type: 'number', min: 0, max: 85, step: 1, default: 45, label: 'View angle (sweep plot)', unit: '°' },
  exposure: { type: 'number', min: 0.1, max: 4, step: 0.05, default: 1, label: 'Sphere exposure' },
  codeDiffuse: { type: 'code', slot: 'diffuse', default: SLOTS.diffuse.starter, label: 'Your diffuse term (GLSL)' },
  params: { type: 'params', default: {}, label: 'Sliders of your code' },
};
