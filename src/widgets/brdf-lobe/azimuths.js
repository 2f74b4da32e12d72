// The light's and the view's azimuths (beyond the talk, issue 28). The lobe is computed in the plane of incidence's
// frame: x towards the mirror side, the light at −x (so θl and θv read as on the polar plot). That frame is turned
// about n from the tangent t so that the light lies at its azimuth φl; the view is turned off the plane by its own
// Δφ (0: in the plane, on the mirror side for θv > 0), so the pair (φl, φv) is free.
import { DEG } from '../../math/angles.js';

/** w turned by `angle` (radians) about n (z). */
export const turnAboutN = ([x, y, z], angle) => [
  x * Math.cos(angle) - y * Math.sin(angle),
  x * Math.sin(angle) + y * Math.cos(angle),
  z,
];

/** The plane of incidence's x axis (its mirror side) from t, radians: opposite the light's azimuth φl. */
export const planeAzimuth = (state) => (state.lightPhi + 180) * DEG;

/** The view's azimuth from t in degrees, 0 to 360 (the side θv's sign picks, turned by Δφ). */
export function viewAzimuth(state) {
  const side = state.viewTheta < 0 ? 0 : 180;
  return (((state.lightPhi + side + state.viewPhi) % 360) + 360) % 360;
}

/** An azimuth in degrees wrapped into [0, 360) (the light's) or [−180, 180) (the view's Δφ). */
export const wrapDegrees = (deg, from = 0) => ((((deg - from) % 360) + 360) % 360) + from;
