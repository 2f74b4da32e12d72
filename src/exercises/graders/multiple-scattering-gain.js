// The grader 'multiple-scattering-gain': Energy that multiple bounces give back.
// Its fields follow the grader contract in src/exercises/graders.js.
import { randomWalkAlbedoGGX } from '../../math/random-walk.js';
import { DEG } from '../../math/angles.js';
import { fmt, offBy } from './feedback.js';

export const grader = {
  title: 'Energy that multiple bounces give back',
  summary:
    'The percentage points of albedo a GGX metal (height-correlated Smith, Schlick’s F of F0 at every bounce) ' +
    'gains ' +
    'from light that bounces more than once: 100 (A − A₁), A the albedo and A₁ its first bounce, by the ' +
    'random walk on the ' +
    'Smith microsurface (Heitz et al. 2016; 100 000 seeded paths, standard error about 0.1 point).',
  answer: { kind: 'number', label: 'Energy given back', unit: 'percentage points' },
  widget: null,
  params: {
    alpha: { type: 'number', min: 0.05, max: 1, required: true, label: 'α' },
    f0: { type: 'number', min: 0, max: 1, required: true, label: 'F0' },
    thetaDeg: { type: 'number', min: 0, max: 85, default: 0, label: 'view angle (°)' },
  },
  tolerance: 'percentage points either side',
  grade({ answer, params, tolerance }) {
    const walk = randomWalkAlbedoGGX(Math.cos(params.thetaDeg * DEG), params.alpha, params.f0, 100_000, 1);
    const gain = 100 * (walk.albedo - walk.single);
    const where =
      `at α = ${params.alpha}, F0 = ${params.f0}, θ = ${params.thetaDeg}° one bounce reflects ` +
      `${fmt(100 * walk.single)}% and all bounces ${fmt(100 * walk.albedo)}%`;
    if (Math.abs(answer - gain) <= tolerance)
      return {
        ok: true,
        summary: `Right: ${where}, ${fmt(gain)} points more (within ±${fmt(tolerance)}).`,
        details: [],
      };
    return {
      ok: false,
      summary: `${offBy(answer, gain, ' points')}; needs to be within ±${fmt(tolerance)} points.`,
      details: [
        answer < gain
          ? 'More comes back than that: a metal reflects most of what reaches a second facet, so most of what ' +
            'single scattering loses returns.'
          : 'Less comes back than that: only what single scattering loses (1 − E with F = 1) can return, and ' +
            'each bounce keeps only F of it.',
      ],
    };
  },
};
