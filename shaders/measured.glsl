// A measured BRDF in the MERL layout (Matusik et al. 2003), as a 3-D texture: width phi_d (180 texels over
// [0, pi), repeating: reciprocity), height theta_d (90 over [0, pi/2]), depth theta_h (90, at sqrt(theta_h /
// (pi/2)) · 90). Texel centres are the nodes, so hardware trilinear filtering is merl.js's valueAt (except that
// missing nodes read 0 here). The twin of src/measured/merl.js.
#include "common.glsl"

uniform highp sampler3D uMeasured;

// The reference reader's angles of (l, v) about n, from dot and cross products only (any frame): after h is
// turned onto n, n lies at azimuth pi, so the x axis is the part of -n across h.
vec3 merlCoordinates(vec3 n, vec3 l, vec3 v) {
  vec3 h = normalize(l + v);
  float nh = dot(n, h);
  float thetaH = atan(length(cross(n, h)), nh); // atan, not acos: precise near n
  vec3 x = nh * h - n;
  float lx = length(x);
  x = lx > 1e-6 ? x / lx : normalize(cross(h, abs(h.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 y = cross(h, x);
  float thetaD = atan(length(cross(l, h)), dot(l, h));
  float phiD = atan(dot(l, y), dot(l, x));
  if (phiD < 0.0) phiD += PI;
  return vec3(phiD / PI * 180.0, thetaD / (0.5 * PI) * 90.0, sqrt(thetaH / (0.5 * PI)) * 90.0);
}

// f(l, v) in 1/sr per channel; 0 at or below the horizon.
vec3 measuredBRDF(vec3 n, vec3 l, vec3 v) {
  if (dot(n, l) <= 0.0 || dot(n, v) <= 0.0) return vec3(0.0);
  vec3 c = merlCoordinates(n, l, v);
  return texture(uMeasured, (c + 0.5) / vec3(180.0, 90.0, 90.0)).rgb;
}
