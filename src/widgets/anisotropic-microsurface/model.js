// anisotropic-microsurface, its model as pure functions: the surface of the state, the direction of a polar angle
// and an azimuth, the ray-traced G1 at one azimuth and Smith's for the surface's own roughness pair.
import { DEG } from '../../math/angles.js';
import { smithG1BeckmannAniso } from '../../math/anisotropic.js';
import { cellMaxima, facetAlphas, generateHeightfield, measuredG1Aniso } from '../../math/heightfield.js';

export const GRID = 192; // cells per side of the periodic surface: ~38 of its shortest bumps
export const SAMPLES = 12000; // facets ray-traced per azimuth: a standard error of G1 under ~0.007
export const AZIMUTHS_MEASURED = Array.from({ length: 13 }, (_, i) => i * 15); // degrees from t
export const AZIMUTHS_CURVE = Float64Array.from({ length: 181 }, (_, i) => i);

/** The unit direction at `thetaDeg` from n and `phiDeg` from t: [x, y, z] in (t, b, n). */
export function directionOf(thetaDeg, phiDeg) {
  const [t, p] = [thetaDeg * DEG, phiDeg * DEG];
  return [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
}

const MIN_LENGTH = 5; // cells of the full grid across the shortest bump (heightfield.js's default)

/**
 * The state's random surface: its heights, cell maxima and the roughness pair its facets have. `every` 2: every
 * other point of the same surface (its waves and heights in cells of twice the size: a quarter of the work, while a
 * control moves; its facets, over twice the span, come out a little smoother).
 */
export function createSurface(state, every = 1) {
  const options = { seed: state.seed, minLength: MIN_LENGTH / every };
  const field = generateHeightfield(GRID / every, state.alphaX, state.alphaY, options);
  return { field, maxima: cellMaxima(field), alphas: facetAlphas(field), every };
}

/** Smith's G1 (anisotropic Beckmann) of the direction (θ, φ) over the surface's own pair of α. */
export const smithAt = (surface, thetaDeg, phiDeg) =>
  smithG1BeckmannAniso(...directionOf(thetaDeg, phiDeg), ...surface.alphas);

/** Ray-traced G1 of the direction (θ, φ): { g1, towards, away } (heightfield.js). */
export const measuredAt = (surface, thetaDeg, phiDeg, samples = SAMPLES) =>
  measuredG1Aniso(surface.field, surface.maxima, directionOf(thetaDeg, phiDeg), { samples });

/** Smith's curve against the azimuth, for the plot. */
export const smithCurve = (surface, thetaDeg) => Array.from(AZIMUTHS_CURVE, (p) => smithAt(surface, thetaDeg, p));
