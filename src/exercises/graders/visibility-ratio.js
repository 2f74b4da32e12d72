// The grader 'visibility-ratio': Ratio of two visibility terms.
// Its fields follow the grader contract in src/exercises/graders.js.
import { VISIBILITY_TERMS } from '../../math/brdf.js';
import { DEG } from '../../math/angles.js';
import { termOptions } from '../../math/catalogue/index.js';
import { fmt, offBy } from './feedback.js';

export const VISIBILITY_NAMES = termOptions('visibility');

export const visibilityAtMirror = (term, thetaDeg, alpha) => {
  const c = Math.cos(thetaDeg * DEG);
  return VISIBILITY_TERMS[term]({ nl: c, nv: c, nh: 1, lh: c }, { alpha });
};

export const grader = {
  title: 'Ratio of two visibility terms',
  summary:
    'V_numerator / V_denominator with l and v mirrored about n at `thetaDeg` (h = n), at the widget’s roughness.',
  answer: { kind: 'number', label: 'Ratio', unit: '' },
  widget: 'visibility-explorer',
  given: ['alpha'],
  params: {
    numerator: { type: 'enum', options: VISIBILITY_NAMES, required: true, label: 'numerator term' },
    denominator: { type: 'enum', options: VISIBILITY_NAMES, required: true, label: 'denominator term' },
    thetaDeg: { type: 'number', min: 0, max: 89, required: true, label: 'angle of l and v (°)' },
  },
  tolerance: 'absolute error of the ratio',
  grade({ state, answer, params, tolerance }) {
    const num = visibilityAtMirror(params.numerator, params.thetaDeg, state.alpha);
    const den = visibilityAtMirror(params.denominator, params.thetaDeg, state.alpha);
    const ratio = num / den;
    const what =
      `${VISIBILITY_NAMES[params.numerator]} / ${VISIBILITY_NAMES[params.denominator]} at ` +
      `${params.thetaDeg}°, α = ${state.alpha}`;
    if (Math.abs(answer - ratio) <= tolerance)
      return { ok: true, summary: `Right: ${what} is ${fmt(ratio)} (within ±${fmt(tolerance)}).`, details: [] };
    return {
      ok: false,
      summary: `${offBy(answer, ratio, '')} for ${what}; needs to be within ±${fmt(tolerance)}.`,
      details: ['Read both curves at the angle (hover the plot in the mirrored configuration) and divide.'],
    };
  },
};
