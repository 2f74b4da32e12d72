// The grader 'lambert-radiance': Brightness of a Lambertian surface.
// Its fields follow the grader contract in src/exercises/graders.js.
import { punctualRadiance } from '../../math/brdf.js';
import { diffuseLambert } from '../../math/diffuse.js';
import { DEG } from '../../math/angles.js';
import { fmt, times, offBy } from './feedback.js';

export const grader = {
  title: 'Brightness of a Lambertian surface',
  summary:
    'Radiance of a Lambertian surface (albedo cdiff) under a punctual light c_light at `thetaDeg` from the ' +
    'normal: Lo = π (cdiff/π) c_light cos θ.',
  answer: { kind: 'number', label: 'Radiance Lo', unit: '' },
  widget: null,
  params: {
    cdiff: { type: 'number', min: 0, max: 1, default: 1, label: 'cdiff' },
    cLight: { type: 'number', min: 1e-6, max: 1e6, required: true, label: 'c_light' },
    thetaDeg: { type: 'number', min: 0, max: 90, required: true, label: 'light angle from the normal (°)' },
  },
  tolerance: 'absolute error, in the units of c_light',
  grade({ answer, params, tolerance }) {
    const { cdiff, cLight, thetaDeg } = params;
    const target = punctualRadiance(diffuseLambert(cdiff), Math.cos(thetaDeg * DEG), cLight);
    if (Math.abs(answer - target) <= tolerance)
      return { ok: true, summary: `Right: Lo = ${fmt(target)} (within ±${fmt(tolerance)}).`, details: [] };
    const near = (x) => Math.abs(answer - x) <= tolerance * Math.max(1, x / Math.max(target, 1e-12));
    const details = [];
    if (near(target * Math.PI))
      details.push('That is π times too bright: the π of the punctual light equation cancels Lambert’s 1/π.');
    else if (near(target / Math.PI))
      details.push('That is π times too dark: the punctual light brings a factor π (Lo = π f c_light cos θ).');
    else if (near(cLight * cdiff))
      details.push('You left out the cosine: the light arrives at θ from the normal, spread over a larger area.');
    else if (target > 0) details.push(`Your value is ${times(answer / target)} the right one.`);
    return { ok: false, summary: `${offBy(answer, target, '')}; needs to be within ±${fmt(tolerance)}.`, details };
  },
};
