// The energy widget's compensation view as pure functions: the albedo of a coloured metal (the talk's linear
// F0, per channel) against the view angle, from single scattering, each compensation (from the albedo table, as
// the spheres compute it) and the random walk on the Smith microsurface (the truth they approximate).
import { specularAlbedoFromTable } from '../../math/albedo-table.js';
import { randomWalkAlbedoGGX } from '../../math/random-walk.js';
import { DEG } from '../../math/angles.js';
import { termOptions } from '../../math/catalogue/index.js';

/** The catalogue's compensations, none (single scattering) first. */
export const COMPENSATIONS = Object.keys(termOptions('compensation'));

/** View angles (degrees) where the walk runs, and its paths per angle (standard error ≈ 1e-3). */
export const WALK_DEGREES = [0, 15, 30, 45, 60, 70, 80, 85];
export const WALK_PATHS = 20_000;

/** Per compensation ({ none, kullaConty, turquin }), per view angle (degrees), the [r, g, b] albedo from the table. */
export function albedoCurves(table, alpha, f0rgb, degrees) {
  const at = (deg, f0, compensation) => specularAlbedoFromTable(table, Math.cos(deg * DEG), alpha, f0, compensation);
  const curve = (compensation) => degrees.map((deg) => f0rgb.map((f0) => at(deg, f0, compensation)));
  return Object.fromEntries(COMPENSATIONS.map((compensation) => [compensation, curve(compensation)]));
}

/** The walk at WALK_DEGREES: [{ deg, albedo: [r, g, b], error: [r, g, b] }], seeded per angle. */
export function walkPoints(alpha, f0rgb) {
  return WALK_DEGREES.map((deg, i) => {
    const w = randomWalkAlbedoGGX(Math.cos(deg * DEG), alpha, f0rgb, WALK_PATHS, 1 + i);
    return { deg, albedo: w.albedo, error: w.standardError };
  });
}

/** Saturation of a linear colour, 1 - min/max (HSV's): 0 for grey, 1 when a channel is 0. */
export const saturation = (rgb) => (Math.max(...rgb) > 0 ? 1 - Math.min(...rgb) / Math.max(...rgb) : 0);
