// The grader of the F82-tint exercise (past the talk): how much brighter Schlick's approximation makes a metal's
// channel near grazing than F82-tint (Hoffman 2023, OpenPBR's metal), both fitted to the metal's measured (n, k).
// Computed from src/math when the answer is checked. Listed in src/exercises/graders.js.
import { f82TintFromConductor, fresnelConductor, fresnelF82Tint, fresnelSchlick } from '../../math/fresnel.js';
import { METALS, materialByKey } from '../../math/materials.js';
import { measuredRgbNk } from '../../math/optical-constants.js';
import { DEG } from '../../math/angles.js';

const CHANNELS = { r: 'red (650 nm)', g: 'green (550 nm)', b: 'blue (450 nm)' };
const points = (x) => `${(100 * x).toFixed(2)}%`;

/** Schlick, F82-tint and the exact curve of `metal`'s `channel` at `thetaDeg`, and F82-tint's fit. */
export function f82SchlickGap(metal, channel, thetaDeg) {
  const [eta, k] = measuredRgbNk(metal)['rgb'.indexOf(channel)];
  const { f0, tint } = f82TintFromConductor(eta, k);
  const c = Math.cos(thetaDeg * DEG);
  const schlick = fresnelSchlick(f0, c);
  const f82 = fresnelF82Tint(f0, tint, c);
  return { f0, tint, schlick, f82, exact: fresnelConductor(c, eta, k), gap: 100 * (schlick - f82) };
}

export const grader = {
  title: 'Schlick against F82-tint near grazing',
  summary:
    'How many percentage points brighter Schlick’s approximation makes one channel of a measured metal at ' +
    '`thetaDeg` than F82-tint: 100 (Schlick − F82-tint), both fitted to the metal’s measured (n, k) (F0 exact, ' +
    'F82-tint exact at cos θ = 1/7).',
  answer: { kind: 'number', label: 'Schlick − F82-tint', unit: 'percentage points' },
  widget: null,
  params: {
    metal: {
      type: 'enum',
      options: Object.fromEntries(METALS.map((m) => [m.key, m.name])),
      required: true,
      label: 'metal',
    },
    channel: { type: 'enum', options: CHANNELS, default: 'r', label: 'channel' },
    thetaDeg: { type: 'number', min: 0, max: 90, required: true, label: 'angle of incidence (°)' },
  },
  tolerance: 'percentage points either side',
  grade({ answer, params, tolerance }) {
    const g = f82SchlickGap(params.metal, params.channel, params.thetaDeg);
    const where =
      `at ${params.thetaDeg}° the ${CHANNELS[params.channel]} channel of ${materialByKey(params.metal).name} ` +
      `is ${points(g.schlick)} by Schlick and ${points(g.f82)} by F82-tint (exact: ${points(g.exact)})`;
    if (Math.abs(answer - g.gap) <= tolerance)
      return {
        ok: true,
        summary: `Right: ${where}, ${g.gap.toFixed(2)} points apart (within ±${tolerance}).`,
        details: [],
      };
    const near = (x) => Math.abs(answer - x) <= tolerance;
    const details = [];
    if (near(100 * (g.schlick - g.exact)))
      details.push('That is Schlick against the exact curve; the question compares Schlick with F82-tint.');
    else if (near(-g.gap)) details.push('The sign is turned round: Schlick is the brighter of the two here.');
    else
      details.push(
        `F82-tint is Schlick minus b μ(1 − μ)⁶ with μ = cos θ; the gap is that term. With F0 = ` +
          `${g.f0.toFixed(3)} and tint t = ${g.tint.toFixed(3)}, b = Schlick(F0, 1/7)(1 − t) / ((1/7)(6/7)⁶).`,
      );
    return {
      ok: false,
      summary:
        `${answer.toFixed(2)} points is too ${answer > g.gap ? 'high' : 'low'} by ` +
        `${Math.abs(answer - g.gap).toFixed(2)}; needs to be within ±${tolerance} points.`,
      details,
    };
  },
};
