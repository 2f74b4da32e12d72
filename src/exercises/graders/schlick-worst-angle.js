// The grader 'schlick-worst-angle': Where Schlick is worst.
// Its fields follow the grader contract in src/exercises/graders.js.
import { fresnelDielectric, fresnelSchlick, f0FromIor } from '../../math/fresnel.js';
import { DEG } from '../../math/angles.js';
import { fmt, times, offBy } from './feedback.js';

/** Angle (degrees, 0.01° steps) where Schlick's approximation is furthest from exact Fresnel, and that error. */
export function schlickWorstAngle(ior) {
  const f0 = f0FromIor(ior);
  let best = { deg: 0, error: 0 };
  for (let i = 0; i <= 9000; i++) {
    const c = Math.cos(i * 0.01 * DEG);
    const e = Math.abs(fresnelSchlick(f0, c) - fresnelDielectric(c, ior));
    if (e > best.error) best = { deg: i * 0.01, error: e };
  }
  return best;
}

export const grader = {
  title: 'Where Schlick is worst',
  summary:
    'The angle of incidence at which Schlick’s approximation is furthest from exact Fresnel, for the widget’s ' +
    'custom IOR (0.01° scan).',
  answer: { kind: 'number', label: 'Angle', unit: '°' },
  widget: 'fresnel-curves',
  given: ['ior'],
  params: {},
  tolerance: 'degrees either side',
  grade({ state, answer, tolerance }) {
    const worst = schlickWorstAngle(state.ior);
    const f0 = f0FromIor(state.ior);
    const c = Math.cos(Math.min(Math.max(answer, 0), 90) * DEG);
    const there = Math.abs(fresnelSchlick(f0, c) - fresnelDielectric(c, state.ior));
    if (Math.abs(answer - worst.deg) <= tolerance)
      return {
        ok: true,
        summary:
          `Right: Schlick is worst at ${fmt(worst.deg)}°, off by ${fmt(worst.error)} (within ` +
          `±${fmt(tolerance)}°).`,
        details: [],
      };
    return {
      ok: false,
      summary: `${offBy(answer, worst.deg, '°')}; needs to be within ±${fmt(tolerance)}°.`,
      details: [
        `At ${fmt(answer)}° Schlick is off by ${fmt(there)}; at its worst it is off by ${fmt(worst.error)}, ` +
          `${times(worst.error / Math.max(there, 1e-12))} as much.`,
      ],
    };
  },
};
