// The grader 'fresnel-reflectance-angle': Angle for a reflectance.
// Its fields follow the grader contract in src/exercises/graders.js.
import { fresnelConductor, fresnelDielectric } from '../../math/fresnel.js';
import { fresnelParams, isMetal, materialByKey } from '../../math/materials.js';
import { DEG } from '../../math/angles.js';
import { fmt, pct } from './feedback.js';

/** Exact reflectance of a table material at the 550 nm sample, as the surfaces widget draws it. */
export function interfaceReflectance(material, thetaDeg) {
  const p = fresnelParams(material);
  const c = Math.cos(thetaDeg * DEG);
  return isMetal(material) ? fresnelConductor(c, p.eta[1], p.k[1]) : fresnelDielectric(c, p.eta[1]);
}

export const grader = {
  title: 'Angle for a reflectance',
  summary: 'Set the angle of incidence at which the material reflects `target` (exact Fresnel, 550 nm).',
  answer: { kind: 'state' },
  widget: 'surfaces',
  reads: ['theta'],
  given: ['material'],
  params: { target: { type: 'number', min: 0, max: 1, required: true, label: 'target reflectance' } },
  tolerance: 'reflectance (0–1) either side of the target',
  grade({ state, params, tolerance }) {
    const R = interfaceReflectance(state.material, state.theta);
    const name = materialByKey(state.material).name;
    const where = `At ${state.theta}°, ${name} reflects ${pct(R)}`;
    if (Math.abs(R - params.target) <= tolerance)
      return {
        ok: true,
        summary: `Right: ${where}; the target is ${pct(params.target)} ± ${pct(tolerance)}.`,
        details: [],
      };
    const rising = interfaceReflectance(state.material, Math.min(state.theta + 1, 89.9)) > R;
    const wantUp = params.target > R;
    return {
      ok: false,
      summary:
        `${where}: ${fmt(Math.abs(R - params.target) * 100)} points ` +
        `${R < params.target ? 'below' : 'above'} the target ${pct(params.target)} (needs ± ${pct(tolerance)}).`,
      details: [`${wantUp === rising ? 'Raise' : 'Lower'} the angle of incidence.`],
    };
  },
};
