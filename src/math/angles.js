// Angles: the app works in radians and shows degrees. DEG turns degrees into radians (x * DEG), and
// TO_DEGREES radians into degrees; one name, one meaning everywhere.

/** Radians per degree: `deg * DEG` is in radians. */
export const DEG = Math.PI / 180;

/** Degrees per radian: `rad * TO_DEGREES` is in degrees. */
export const TO_DEGREES = 180 / Math.PI;

/**
 * A unit direction from two angles in degrees: theta from +z (the view direction, or the normal), phi around z
 * from +x. In view space: theta 0° is the viewer's direction, 90° the side; phi 0° right, 90° up.
 */
export function lightDirFromAngles(thetaDeg, phiDeg) {
  const t = thetaDeg * DEG;
  const p = phiDeg * DEG;
  return [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
}
