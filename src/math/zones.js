// The talk's three Fresnel zones by angle of incidence: below 45° the reflectance barely changes,
// from 45° to 75° it changes somewhat, above 75° it goes rapidly to 1.
export const FRESNEL_ZONE_BOUNDS_DEG = [45, 75];
const COS_BOUNDS = FRESNEL_ZONE_BOUNDS_DEG.map((d) => Math.cos((d * Math.PI) / 180));

/** 0, 1 or 2 for the zone of an angle given by its cosine (clamped to [0, 1]). */
export function fresnelZone(cosTheta) {
  const c = Math.min(Math.max(cosTheta, 0), 1);
  return c > COS_BOUNDS[0] ? 0 : c > COS_BOUNDS[1] ? 1 : 2;
}

/**
 * Share of an orthographically viewed sphere's disk in each zone of n·v. A point at distance r from the
 * disk's centre (unit radius) has n·v = sqrt(1 - r²), i.e. angle theta with r = sin(theta), so the disk
 * inside angle theta has area share sin²(theta): the zones hold sin²45°, sin²75° - sin²45°, 1 - sin²75°.
 */
export function sphereZoneFractions() {
  const [a, b] = FRESNEL_ZONE_BOUNDS_DEG.map((d) => Math.sin((d * Math.PI) / 180) ** 2);
  return [a, b - a, 1 - b];
}
