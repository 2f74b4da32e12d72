// The grader 'smith-g1': Masking at a view angle.
// Its fields follow the grader contract in src/exercises/graders.js.
import { smithG1Beckmann, smithG1GGX } from '../../math/visibility.js';
import { DEG } from '../../math/angles.js';
import { fmt } from './feedback.js';

export const grader = {
  title: 'Masking at a view angle',
  summary: 'Set the view angle at which Smith’s G1 (the share of the microsurface seen, not masked) equals `target`.',
  answer: { kind: 'state' },
  widget: 'microfacets',
  reads: ['viewTheta'],
  given: ['kind', 'alpha'],
  params: { target: { type: 'number', min: 0, max: 1, required: true, label: 'target G1' } },
  tolerance: 'G1 (0–1) either side of the target',
  grade({ state, params, tolerance }) {
    const G1 = (state.kind === 'ggx' ? smithG1GGX : smithG1Beckmann)(
      Math.cos(Math.abs(state.viewTheta) * DEG),
      state.alpha,
    );
    const where = `At θv = ${state.viewTheta}°, G1 = ${fmt(G1)}`;
    if (Math.abs(G1 - params.target) <= tolerance)
      return {
        ok: true,
        summary: `Right: ${where}; the target is ${fmt(params.target)} ± ${fmt(tolerance)}.`,
        details: [],
      };
    return {
      ok: false,
      summary:
        `${where}: ${fmt(Math.abs(G1 - params.target))} ${G1 > params.target ? 'above' : 'below'} the ` +
        `target ${fmt(params.target)} (needs ± ${fmt(tolerance)}).`,
      details: [
        G1 > params.target
          ? 'Too little is masked: view the surface at a more grazing angle.'
          : 'Too much is masked: view the surface closer to its normal.',
      ],
    };
  },
};
