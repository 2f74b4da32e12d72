// The grader 'transmittance-depth': Water depth for a transmittance.
// Its fields follow the grader contract in src/exercises/graders.js.
import { transmittance, waterAbsorptionRgb } from '../../math/media.js';
import { fmt, pct, offBy } from './feedback.js';

const CHANNELS = { r: 'red (650 nm)', g: 'green (550 nm)', b: 'blue (450 nm)' };

/** Water depth (m) at which channel `ch` keeps `threshold` of its light. */
export const depthForTransmittance = (ch, threshold) => -Math.log(threshold) / waterAbsorptionRgb()['rgb'.indexOf(ch)];

export const grader = {
  title: 'Water depth for a transmittance',
  summary:
    'The depth of clear water (Hale & Querry) at which one RGB channel keeps `threshold` of its light: d = ' +
    '−ln(threshold) / σa.',
  answer: { kind: 'number', label: 'Depth', unit: 'm' },
  widget: null,
  params: {
    channel: { type: 'enum', options: CHANNELS, default: 'r', label: 'channel' },
    threshold: { type: 'number', min: 1e-6, max: 0.99, default: 0.01, label: 'threshold' },
  },
  tolerance: 'metres either side of the depth',
  grade({ answer, params, tolerance }) {
    const target = depthForTransmittance(params.channel, params.threshold);
    const sigma = waterAbsorptionRgb()['rgb'.indexOf(params.channel)];
    const left = transmittance(sigma, answer);
    const name = CHANNELS[params.channel];
    if (Math.abs(answer - target) <= tolerance) {
      return {
        ok: true,
        summary:
          `Right: at ${fmt(answer)} m water keeps ${pct(left)} of the ${name} light; the threshold is ` +
          `${pct(params.threshold)} (within ±${fmt(tolerance)} m).`,
        details: [],
      };
    }
    return {
      ok: false,
      summary: `${offBy(answer, target, ' m')}; needs to be within ±${fmt(tolerance)} m.`,
      details: [
        `At ${fmt(answer)} m, ${pct(left)} of the ${name} light is left; the exercise asks where ` +
          `${pct(params.threshold)} is left.`,
        answer < target ? 'Go deeper.' : 'The light was already below the threshold at a shallower depth.',
      ],
    };
  },
};
