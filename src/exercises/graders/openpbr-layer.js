// The grader 'openpbr-layer' (past the talk, issue 29): which of OpenPBR Surface's layers makes a highlight. The
// widget shows the whole lobe of a material, its layers' parts hidden; the student picks the layer whose part is
// most of the lobe's luminance at the light and view of the question, from openPbrLayers when it is checked.
// Listed in src/exercises/graders.js.
import {
  OPENPBR_KEYS,
  OPENPBR_LAYERS,
  LAYER_KEYS,
  layerLuminances,
  openPbrSpec,
} from '../../widgets/brdf-lobe/openpbr-lobe.js';
import { lightDir, viewDir } from '../../widgets/brdf-lobe/model.js';
import { schema as LOBE } from '../../widgets/brdf-lobe/schema.js';
import { pct } from './feedback.js';

const LAYER_NAMES = Object.fromEntries(LAYER_KEYS.map((k) => [k, OPENPBR_LAYERS[k].label]));

/** Each layer's share of the lobe's luminance at the question's light and view, for the params' material. */
export function layerShares(params) {
  const spec = openPbrSpec({ ...params, anisotropy: 0, lightPhi: LOBE.lightPhi.default });
  const y = layerLuminances(lightDir(params.lightTheta), viewDir(params.viewTheta), spec);
  return Object.fromEntries(LAYER_KEYS.map((k) => [k, y.all > 0 ? y[k] / y.all : 0]));
}

/** The layers whose share is above `tolerance`. */
const above = (shares, tolerance) => LAYER_KEYS.filter((k) => shares[k] > tolerance);

export const grader = {
  title: 'Which OpenPBR layer makes the highlight',
  summary:
    'The widget shows the lobe of an OpenPBR material (the params, as the brdf-lobe widget names them) with its ' +
    'layers’ parts hidden; a choice is right when that layer makes more than `tolerance` of the lobe’s luminance ' +
    'at light `lightTheta` and view `viewTheta`.',
  answer: { kind: 'choice', choices: () => LAYER_NAMES },
  widget: null,
  params: {
    ...Object.fromEntries(OPENPBR_KEYS.map((k) => [k, LOBE[k]])),
    lightTheta: { ...LOBE.lightTheta, required: true },
    viewTheta: { ...LOBE.viewTheta, required: true },
  },
  tolerance: 'share of the lobe’s luminance (0.5 to 1) the chosen layer must make',
  /** Well posed: exactly one layer makes more than the share (a share of at least one half allows no second). */
  check(params, tolerance) {
    if (!(tolerance >= 0.5 && tolerance < 1)) return [`the tolerance ${tolerance} is not a share from 0.5 to 1`];
    const shares = layerShares(params);
    const right = above(shares, tolerance);
    if (right.length === 1) return [];
    const largest = LAYER_KEYS.reduce((a, k) => (shares[k] > shares[a] ? k : a));
    return [
      `no layer makes more than ${pct(tolerance)} of the lobe (the largest, ${largest}, ${pct(shares[largest])})`,
    ];
  },
  grade({ answer, params, tolerance }) {
    const shares = layerShares(params);
    const [right] = above(shares, tolerance);
    const where = `at θl = ${params.lightTheta}°, θv = ${params.viewTheta}°`;
    if (answer === right)
      return {
        ok: true,
        summary: `Right: the ${LAYER_NAMES[right]} makes ${pct(shares[right])} of the lobe ${where}.`,
        details: [],
      };
    return {
      ok: false,
      summary: `The ${LAYER_NAMES[answer]} makes only ${pct(shares[answer])} of the lobe ${where}.`,
      details: [
        'Switch layers off one at a time in the OpenPBR folder (coat_weight, fuzz_weight, base_metalness) and ' +
          'watch which one takes the highlight with it.',
      ],
    };
  },
};
