// The grader 'albedo-loss': Energy lost by single scattering.
// Its fields follow the grader contract in src/exercises/graders.js.
import { albedoGGX } from '../../math/integrate.js';
import { DEG } from '../../math/angles.js';
import { fmt, offBy } from './feedback.js';

export const grader = {
  title: 'Energy lost by single scattering',
  summary:
    'The percentage of light a GGX surface (height-correlated Smith, F = 1) fails to reflect at one angle: ' +
    '100 (1 − E(μ)), E by deterministic quadrature (albedoGGX, within 1e-5).',
  answer: { kind: 'number', label: 'Energy lost', unit: '%' },
  widget: null,
  params: {
    alpha: { type: 'number', min: 0.01, max: 1, required: true, label: 'α' },
    thetaDeg: { type: 'number', min: 0, max: 89, default: 0, label: 'view angle (°)' },
  },
  tolerance: 'percentage points either side',
  grade({ answer, params, tolerance }) {
    const loss = 100 * (1 - albedoGGX(Math.cos(params.thetaDeg * DEG), params.alpha));
    if (Math.abs(answer - loss) <= tolerance)
      return {
        ok: true,
        summary:
          `Right: the white furnace loses ${fmt(loss)}% at α = ${params.alpha}, θ = ` +
          `${params.thetaDeg}° (within ±${fmt(tolerance)} points).`,
        details: [],
      };
    return {
      ok: false,
      summary: `${offBy(answer, loss, '%')}; needs to be within ±${fmt(tolerance)} points.`,
      details: [
        answer < loss
          ? 'More light is lost than that: rough surfaces send much of it into second bounces that single ' +
            'scattering ignores.'
          : 'Less is lost than that: read the albedo E at the angle, the loss is 1 − E.',
      ],
    };
  },
};
