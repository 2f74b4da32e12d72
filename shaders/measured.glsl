// A measured BRDF in the MERL layout (Matusik et al. 2003), as a 3-D texture: width phi_d (180 texels over
// [0, pi), repeating: reciprocity), height theta_d (90 over [0, pi/2]), depth theta_h (90, at sqrt(theta_h /
// (pi/2)) · 90). Texel centres are the nodes, so hardware trilinear filtering is merl.js's valueAt (except that
// missing nodes read 0 here). The twin of src/measured/merl.js.
#include "common.glsl"

uniform highp sampler3D uMeasured;

// Node coordinates (theta_h, theta_d, phi_d) of (l, v) about n, as merlCoordinates in merl.js: the reference
// reader's angles from dot and cross products only (any frame). Once h is turned onto n, n lies at azimuth pi:
// the frame is y = n × h / |n × h|, x = y × h. phi_d is read from d = l - h, not l (h·x = h·y = 0): l·x
// would cancel to float32 noise when l is near h (0.07° off at theta_d = 0.2°; this way 1e-5°). With h on n
// the reader's frame is n's own (phi_h = 0): x = (1, 0, 0) for n = z, the sphere shader's tangent otherwise.
vec3 merlCoordinates(vec3 n, vec3 l, vec3 v) {
  vec3 h = normalize(l + v);
  vec3 nxh = cross(n, h);
  float s = length(nxh);
  float thetaH = atan(s, dot(n, h)); // atan, not acos: precise near n
  vec3 tangent = abs(n.z) < 0.999 ? normalize(cross(vec3(0.0, 0.0, 1.0), n)) : vec3(1.0, 0.0, 0.0);
  vec3 y = s > 1e-7 ? nxh / s : cross(n, tangent);
  vec3 x = cross(y, h);
  vec3 d = l - h;
  float thetaD = atan(length(cross(l, h)), dot(l, h));
  // l = v (h = l): d has no part across h, and GLSL ES 3.00 leaves atan(0, 0) undefined (llvmpipe: 3pi/4). Below a
  // float32 ulp of a unit vector the angle is rounding noise (and at theta_d = 0 every phi_d is the same pair): 0.
  float dx = dot(d, x);
  float dy = dot(d, y);
  float phiD = dx * dx + dy * dy > 1e-12 ? atan(dy, dx) : 0.0;
  if (phiD < 0.0) phiD += PI;
  return vec3(sqrt(thetaH / (0.5 * PI)) * 90.0, thetaD / (0.5 * PI) * 90.0, phiD / PI * 180.0);
}

// f(l, v) in 1/sr per channel; 0 at or below the horizon.
vec3 measuredBRDF(vec3 n, vec3 l, vec3 v) {
  if (dot(n, l) <= 0.0 || dot(n, v) <= 0.0) return vec3(0.0);
  vec3 c = merlCoordinates(n, l, v);
  return texture(uMeasured, (c.zyx + 0.5) / vec3(180.0, 90.0, 90.0)).rgb; // the texture's x is phi_d
}
