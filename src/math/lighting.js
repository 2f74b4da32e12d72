// Illumination models besides the punctual light (brdf.js): a distant sphere light by the representative
// point of Karis 2013, and the radiance it stands for. Directions are unit vectors in the local frame
// (n = z); a sphere light is its centre direction d, its angular radius (as sin θs) and its radiance.

/**
 * c_light of a sphere light: the radiance of a white Lambertian surface facing it. A uniform cap of angular
 * radius θs gives irradiance π · L · sin²θs, and the surface sends 1/π of it back: L · sin²θs. The punctual
 * light with this c_light is its limit θs → 0.
 */
export function sphereLightCLight(radiance, sinRadius) {
  return radiance * sinRadius * sinRadius;
}

/**
 * The point of the light closest to the reflected ray r, as a unit direction: the sphere sits at distance 1
 * along d with radius sinθs, so c = (d·r) r - d points from its centre to the ray, and the representative
 * point is d + c·min(sinθs/|c|, 1). When r meets the sphere it is r's own direction.
 */
export function sphereLightRepresentativeDir(r, d, sinRadius) {
  const dr = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
  const c = [dr * r[0] - d[0], dr * r[1] - d[1], dr * r[2] - d[2]];
  const len = Math.hypot(...c);
  const t = len > sinRadius ? sinRadius / len : 1;
  const p = [d[0] + t * c[0], d[1] + t * c[1], d[2] + t * c[2]];
  const pl = Math.hypot(...p);
  return pl > 0 ? p.map((x) => x / pl) : [...d];
}

/**
 * Karis's energy normalisation for the representative point: the lobe is widened to α' = min(α + sinθs/2, 1)
 * (the reflected lobe is about 2α wide, the light adds θs), and GGX's peak scales as 1/α², so (α/α')², at most 1.
 */
export function sphereLightNormalization(alpha, sinRadius) {
  const widened = Math.min(alpha + sinRadius / 2, 1);
  return widened > 0 ? Math.min((alpha / widened) ** 2, 1) : 1;
}

/**
 * The equirectangular map of directions d (y up, any length > 0), as three.js lays out environment maps:
 * u = atan2(z, x)/2π + ½, v = asin(y/|d|)/π + ½ (v = 1 at the zenith), the elevation taken as atan2(y, |(x, z)|).
 * At the poles (x = z = 0, where GLSL leaves atan(0, 0) undefined) u = ½, for ±0 alike; d = 0 maps to (½, ½).
 */
export function equirectUv(d) {
  const horizontal = Math.hypot(d[0], d[2]);
  if (horizontal === 0) return [0.5, d[1] > 0 ? 1 : d[1] < 0 ? 0 : 0.5];
  return [Math.atan2(d[2], d[0]) / (2 * Math.PI) + 0.5, Math.atan2(d[1], horizontal) / Math.PI + 0.5];
}

/** The direction at (u, v) of the equirectangular map: the inverse of equirectUv. */
export function equirectDirection(u, v) {
  const phi = (u - 0.5) * 2 * Math.PI;
  const el = (v - 0.5) * Math.PI;
  return [Math.cos(el) * Math.cos(phi), Math.sin(el), Math.cos(el) * Math.sin(phi)];
}
