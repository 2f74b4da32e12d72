// The multiple-scattering lobe beside the single-scattering one, for GGX with height-correlated Smith (the
// model both are defined for): Kulla & Conty's lobe times its Fresnel factor, and the random walk's multiply
// scattered part (all bounces but the first) at a few view angles, with its Monte Carlo standard error.
import {
  averageAlbedoGGX,
  fresnelAverage,
  fresnelMultipleScatteringKullaConty,
  multipleScatteringKullaConty,
} from '../../math/multiple-scattering.js';
import { randomWalkBRDFGGX } from '../../math/random-walk.js';

/** View angles (degrees, + on the mirror side) where the walk is run, and its paths per angle. */
export const WALK_ANGLES = [-80, -65, -50, -35, -20, -5, 5, 20, 35, 50, 65, 80];
export const WALK_SAMPLES = 3000;

/** Kulla & Conty's lobe is built for GGX with height-correlated Smith; other pairs and user-written terms get none. */
export const hasMultipleLobe = (spec) =>
  spec.D === 'ggx' && spec.V === 'smithGGXCorrelated' && !Object.keys(spec.custom ?? {}).length;

/** f_ms(l, v) F_ms in 1/sr (F_ms = 1 when Fresnel is off or F = 1). */
export function kullaContyLobe(l, v, alpha, f0OrOne) {
  const factor = fresnelMultipleScatteringKullaConty(fresnelAverage(f0OrOne), averageAlbedoGGX(alpha));
  return multipleScatteringKullaConty(l[2], v[2], alpha) * factor;
}

/** The walk's multiply scattered part of f(l, v): { value, error } (error: the standard error of the whole walk). */
export function walkMultiplePart(l, v, alpha, f0OrOne, seed) {
  const r = randomWalkBRDFGGX(l, v, alpha, f0OrOne, WALK_SAMPLES, seed);
  return { value: r.value - r.single, error: r.standardError };
}
