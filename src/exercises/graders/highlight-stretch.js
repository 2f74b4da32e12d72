// The grader 'highlight-stretch': Which way the highlight stretches.
// Its fields follow the grader contract in src/exercises/graders.js.
import { anisotropicSphere, highlightSpread } from '../sphere-image.js';
import { fmt } from './feedback.js';

export const STRETCH_CHOICES = {
  tangent: 'Along the tangent: left to right',
  bitangent: 'Across the tangent: bottom to top',
  round: 'Neither: the highlight stays round',
};

/**
 * The highlight of anisotropic GGX at (αx, αy), its spread along x and y (pixels) and the right choice: round when
 * the two spreads are within the factor `round` of each other.
 */
export function stretchOf({ alphaX, alphaY, lightTheta, size }, round) {
  const [x, y] = highlightSpread(anisotropicSphere(size, lightTheta, [alphaX, alphaY]));
  const ratio = x / y;
  const answer = ratio > round ? 'tangent' : ratio < 1 / round ? 'bitangent' : 'round';
  return { x, y, ratio, answer };
}

export const grader = {
  title: 'Which way the highlight stretches',
  summary:
    'Anisotropic GGX at (αx, αy), the tangent left to right across the sphere as on the NDF explorer: the right ' +
    'choice is the axis along which the highlight (pixels above half its peak) reaches furthest, measured on the ' +
    'JS picture; round when the two reaches are within the factor `tolerance` of each other.',
  answer: { kind: 'choice', choices: () => STRETCH_CHOICES },
  widget: 'ndf-explorer',
  params: {
    alphaX: { type: 'number', min: 0.01, max: 1, required: true, label: 'αx (along the tangent)' },
    alphaY: { type: 'number', min: 0.01, max: 1, required: true, label: 'αy (along the bitangent)' },
    lightTheta: { type: 'number', min: 0, max: 60, default: 20, label: 'light angle from the view (°)' },
    size: { type: 'number', min: 32, max: 128, default: 64, label: 'grid size' },
  },
  tolerance: 'factor (> 1) within which the two reaches count as the same: a round highlight',
  /** Well posed: the reaches differ clearly (by 1.5 times the tolerance's factor), or are clearly the same. */
  check(params, tolerance) {
    const { ratio } = stretchOf(params, tolerance);
    const clear = ratio > 1.5 * tolerance || ratio < 1 / (1.5 * tolerance) || Math.abs(ratio - 1) < 0.05;
    return clear ? [] : [`the highlight’s reaches are ${fmt(ratio)}× apart: too close to call`];
  },
  grade({ answer, params, tolerance }) {
    const s = stretchOf(params, tolerance);
    const measured =
      `On this sphere the highlight reaches ${fmt(s.x, 2)} pixels left to right and ${fmt(s.y, 2)} bottom to top ` +
      `(RMS distance from its middle, over the pixels above half its peak).`;
    if (answer === s.answer)
      return {
        ok: true,
        summary: `Right: ${STRETCH_CHOICES[answer].toLowerCase()}. ${measured}`,
        details: [
          'The microfacet normals spread further where α is larger, so the highlight does too. On brushed metal ' +
            'the slopes vary most across the scratches: the larger α is across the brushing, and the highlight ' +
            'stretches across it.',
        ],
      };
    return {
      ok: false,
      summary: `Not quite. ${measured}`,
      details: ['Which way do the normals of the microfacets tilt more: along x, where α is αx, or along y?'],
    };
  },
};
