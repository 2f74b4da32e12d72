// The grader 'sphere-match': Match a sphere.
// Its fields follow the grader contract in src/exercises/graders.js.
import { microfacetBRDFAt } from '../../math/brdf.js';
import { displayRms, highlightArea, peakOf, sphereRadiance } from '../sphere-image.js';
import { fmt, times } from './feedback.js';

/** The sphere the sphere-match grader compares: GGX, height-correlated Smith, Schlick. */
export function materialSphere({ f0, alpha }, { lightTheta, size }) {
  const p = { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', f0, alpha };
  return sphereRadiance(size, lightTheta, (a) => microfacetBRDFAt(a, p));
}

export const grader = {
  title: 'Match a sphere',
  summary:
    'Match the target sphere (GGX, height-correlated Smith, Schlick F with F0 and α) by the RMS difference of ' +
    'the two pictures on a size × size grid.',
  answer: { kind: 'state' },
  widget: 'brdf-lobe',
  reads: ['f0', 'alpha'],
  requires: { D: 'ggx', V: 'smithGGXCorrelated', F: 'schlick' },
  params: {
    f0: { type: 'number', min: 0, max: 1, required: true, label: 'target F0' },
    alpha: { type: 'number', min: 0.02, max: 1, required: true, label: 'target α' },
    lightTheta: { type: 'number', min: 0, max: 89, default: 30, label: 'light angle from the view (°)' },
    exposure: { type: 'number', min: 0.01, max: 100, default: 1, label: 'exposure' },
    size: { type: 'number', min: 8, max: 128, default: 48, label: 'grid size' },
  },
  tolerance: 'RMS difference of the display values (0–1, sRGB-encoded, clamped) over the sphere’s pixels',
  grade({ state, params, tolerance }) {
    const target = materialSphere(params, params);
    const yours = materialSphere(state, params);
    const rms = displayRms(yours, target, params.exposure);
    const verdict = `RMS error ${fmt(rms, 2)} (display value 0–1), needs < ${fmt(tolerance, 2)}.`;
    if (rms < tolerance) return { ok: true, summary: `Right: ${verdict.replace('needs <', 'under')}`, details: [] };
    const details = [];
    const peak = peakOf(yours) / peakOf(target);
    const area = highlightArea(yours) / highlightArea(target);
    if (Math.abs(peak - 1) > 0.05)
      details.push(`Your highlight is ${times(peak)} as bright as the target’s at its peak.`);
    if (Math.abs(area - 1) > 0.05)
      details.push(`Your highlight covers ${times(area)} the target’s area (pixels above half its peak).`);
    if (Math.abs(state.alpha - params.alpha) > 0.015)
      details.push(`Roughness too ${state.alpha < params.alpha ? 'low' : 'high'}.`);
    if (Math.abs(state.f0 - params.f0) > 0.015) details.push(`F0 too ${state.f0 < params.f0 ? 'low' : 'high'}.`);
    return { ok: false, summary: verdict, details };
  },
};
