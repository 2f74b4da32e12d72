// The visibility explorer's numbers, from src/math only: G = V·(n·l)(n·v) of each chosen term as the light
// sweeps, its difference from height-correlated Smith, and the largest difference up to 80°.
import { VISIBILITY_TERMS, brdfAngles } from '../../math/brdf.js';
import { DEG } from '../../math/angles.js';
import { seriesStyle } from '../../core/ui/palettes.js';
import { termLabel } from '../../math/catalogue/index.js';
import { schema } from './schema.js';

/** The term every other is measured against. */
export const REFERENCE = 'smithGGXCorrelated';

export const ANGLES = Float64Array.from({ length: 357 }, (_, i) => i * 0.25); // 0..89°

/** l and v at angle `deg` (degrees): mirrored about n, or l sweeping past a view fixed at viewTheta. */
function directions(state, deg) {
  const t = deg * DEG;
  if (state.config === 'mirror') return { l: [Math.sin(t), 0, Math.cos(t)], v: [-Math.sin(t), 0, Math.cos(t)] };
  const tv = state.viewTheta * DEG;
  return { l: [Math.sin(t), 0, Math.cos(t)], v: [-Math.sin(tv), 0, Math.cos(tv)] };
}

/** (n·l, n·v) at each of ANGLES for the state's directions: where the user's V is evaluated (custom.js). */
export const cosinesOf = (state) =>
  Array.from(ANGLES, (deg) => {
    const { l, v } = directions(state, deg);
    const a = brdfAngles(l, v);
    return [a.nl, a.nv];
  });

export const CUSTOM = 'custom';

/**
 * One curve per chosen term: { key, label, stroke, dash, G (over ANGLES), error (% from the reference, null
 * where it is 0), worst (largest |error| up to 80°) }. The user's V (`custom`) is drawn from `customG`, its G over
 * ANGLES read back from the GPU, once there is one.
 */
export function visibilityCurves(state, customG = null) {
  const params = { alpha: state.alpha };
  const evalTerm = (key) =>
    ANGLES.map((deg) => {
      const { l, v } = directions(state, deg);
      const a = brdfAngles(l, v);
      return VISIBILITY_TERMS[key](a, params) * a.nl * a.nv;
    });
  const reference = evalTerm(REFERENCE);
  const keys = state.V.filter((key) => key !== CUSTOM || customG);
  return keys.map((key) => {
    const G = key === CUSTOM ? customG : evalTerm(key);
    const error = G.map((g, i) => (reference[i] > 1e-9 ? (100 * (g - reference[i])) / reference[i] : null));
    const within = error.filter((e, i) => e !== null && ANGLES[i] <= 80);
    return {
      key,
      label: termLabel('visibility', key),
      ...seriesStyle(Object.keys(schema.V.options).indexOf(key)),
      G,
      error,
      worst: Math.max(...within.map(Math.abs)),
    };
  });
}

/** The sphere point the page points to: on the lit side, its normal this far from the view towards the light. */
export const RIM_DEG = 60;

/**
 * Each catalogue term's radiance at that point over height-correlated Smith's (D and F are the same on every
 * sphere, so the ratio is V's): [{ key, label, ratio }]. In n's frame v is RIM_DEG from n and l lies in the same
 * plane, lightTheta from v (the spheres' light is lightTheta from the view): above the horizon for every lightTheta.
 */
export function rimRatios(state) {
  const t = (RIM_DEG - state.lightTheta) * DEG;
  const r = RIM_DEG * DEG;
  const a = brdfAngles([Math.sin(t), 0, Math.cos(t)], [Math.sin(r), 0, Math.cos(r)]);
  const params = { alpha: state.alpha };
  const reference = VISIBILITY_TERMS[REFERENCE](a, params);
  return state.V.filter((key) => key !== CUSTOM && key !== REFERENCE).map((key) => ({
    key,
    label: termLabel('visibility', key),
    ratio: VISIBILITY_TERMS[key](a, params) / reference,
  }));
}
