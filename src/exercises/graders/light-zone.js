// The grader 'light-zone': Place the light for a Fresnel zone.
// Its fields follow the grader contract in src/exercises/graders.js.
import { FRESNEL_ZONE_BOUNDS_DEG, fresnelZone } from '../../math/zones.js';
import { DEG } from '../../math/angles.js';
import { fmt } from './feedback.js';

const ZONES = { green: 'green (θ < 45°)', yellow: 'yellow (45°–75°)', red: 'red (θ > 75°)' };

export const grader = {
  title: 'Place the light for a Fresnel zone',
  summary:
    'Move the light so that l·h falls in `zone` (orthographic view: l·h = cos(θ/2) everywhere, θ the light’s ' +
    'angle from the view).',
  answer: { kind: 'state' },
  widget: 'fresnel-zones',
  reads: ['lightTheta'],
  requires: { mode: 'zones-lh', camera: 'orthographic' },
  params: { zone: { type: 'enum', options: ZONES, required: true, label: 'zone' } },
  tolerance: 'degrees by which θd = θ/2 must clear the zone’s boundaries',
  grade({ state, params, tolerance }) {
    const thetaD = state.lightTheta / 2;
    const got = Object.keys(ZONES)[fresnelZone(Math.cos(thetaD * DEG))];
    const want = Object.keys(ZONES).indexOf(params.zone);
    const [lo, hi] = [[0, ...FRESNEL_ZONE_BOUNDS_DEG][want], [...FRESNEL_ZONE_BOUNDS_DEG, 90][want]];
    const clears = thetaD >= lo + (lo > 0 ? tolerance : 0) && thetaD <= hi - (hi < 90 ? tolerance : 0);
    const where =
      `The light is ${state.lightTheta}° from the view, so θd = ${fmt(thetaD)}° and l·h = ` +
      `${fmt(Math.cos(thetaD * DEG))}: the object is ${got}`;
    if (got === params.zone && clears) return { ok: true, summary: `Right: ${where}.`, details: [] };
    const gap = thetaD < lo + tolerance ? lo + tolerance - thetaD : thetaD - (hi - tolerance);
    return {
      ok: false,
      summary:
        `${where}; the exercise wants it ${ZONES[params.zone]}, with θd at least ${fmt(tolerance)}° ` +
        `inside the zone.`,
      details: [
        `Move the light about ${fmt(2 * gap, 2)}° ${thetaD < lo + tolerance ? 'further from' : 'closer to'} ` +
          `the view (θd changes half as fast as the light).`,
      ],
    };
  },
};
