// The grader 'aniso-pair': Which (αx, αy) made the highlight.
// Its fields follow the grader contract in src/exercises/graders.js.
import { anisotropicSphere, displayRms, highlightSpread, peakOf } from '../sphere-image.js';
import { fmt, times } from './feedback.js';

/** The pairs a question offers, key → [αx, αy]: the same roughnesses stretched either way, and round. */
export const ALPHA_PAIRS = {
  wideX: [0.4, 0.1],
  wideY: [0.1, 0.4],
  round: [0.2, 0.2],
  slightX: [0.3, 0.15],
  slightY: [0.15, 0.3],
};
export const PAIR_NAMES = Object.fromEntries(
  Object.entries(ALPHA_PAIRS).map(([key, [x, y]]) => [key, `αx = ${x}, αy = ${y}`]),
);

/** The picture of one pair, and its exposure: the hidden pair's peak shown at 1. */
export const pairSphere = (key, { lightTheta, size }) => anisotropicSphere(size, lightTheta, ALPHA_PAIRS[key]);

/** RMS difference of two pairs' pictures, both at the exposure that shows the second's peak at 1. */
function pairRms(a, b, params) {
  const target = pairSphere(b, params);
  return displayRms(pairSphere(a, params), target, 1 / peakOf(target));
}

export const grader = {
  title: 'Which (αx, αy) made the highlight',
  summary:
    'The page shows the highlight of anisotropic GGX at a hidden pair (αx, αy) of ALPHA_PAIRS (`hidden`, or a ' +
    'random one), the tangent left to right; a choice is right when its picture is within `tolerance` RMS of ' +
    'the hidden one’s (display values, the hidden peak at 1).',
  answer: { kind: 'choice', choices: () => PAIR_NAMES },
  widget: 'ndf-explorer',
  params: {
    hidden: { type: 'enum', options: { random: 'random', ...PAIR_NAMES }, default: 'random', label: 'hidden pair' },
    lightTheta: { type: 'number', min: 0, max: 60, default: 20, label: 'light angle from the view (°)' },
    size: { type: 'number', min: 32, max: 128, default: 64, label: 'grid size' },
  },
  tolerance: 'RMS difference of the display values (0–1) allowed between the chosen pair’s picture and the hidden',
  /** Well posed: whichever pair is hidden, every other pair's picture is further than the tolerance. */
  check(params, tolerance) {
    const hidden = params.hidden === 'random' ? Object.keys(ALPHA_PAIRS) : [params.hidden];
    const problems = [];
    for (const h of hidden)
      for (const k of Object.keys(ALPHA_PAIRS)) {
        const rms = k === h ? Infinity : pairRms(k, h, params);
        if (rms <= tolerance)
          problems.push(
            `${PAIR_NAMES[k]} is within ${fmt(rms, 2)} RMS of ${PAIR_NAMES[h]}: two answers would be right`,
          );
      }
    return problems;
  },
  hide(params, random = Math.random) {
    if (params.hidden !== 'random') return params.hidden;
    const keys = Object.keys(ALPHA_PAIRS);
    return keys[Math.floor(random() * keys.length)];
  },
  grade({ answer, params, tolerance, hidden }) {
    const rms = pairRms(answer, hidden, params);
    if (rms <= tolerance)
      return { ok: true, summary: `Right: ${PAIR_NAMES[answer]} made it (RMS ${fmt(rms, 2)}).`, details: [] };
    const [mx, my] = highlightSpread(pairSphere(answer, params));
    const [hx, hy] = highlightSpread(pairSphere(hidden, params));
    return {
      ok: false,
      summary:
        `${PAIR_NAMES[answer]} draws a different highlight: RMS ${fmt(rms, 2)}, ` +
        `a match needs ≤ ${fmt(tolerance, 2)}.`,
      details: [
        `Its highlight reaches ${times(mx / hx)} as far left to right as the picture’s, and ${times(my / hy)} as ` +
          'far bottom to top.',
      ],
    };
  },
};
