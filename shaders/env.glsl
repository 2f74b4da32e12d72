// Environment maps: the equirectangular layout of three.js (y up), mirrors equirectUv/equirectDirection of
// src/math/lighting.js.
#include "common.glsl"
vec2 equirectUv(vec3 d) {
  return vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, asin(clamp(d.y, -1.0, 1.0)) / PI + 0.5);
}
vec3 equirectDirection(vec2 uv) {
  float phi = (uv.x - 0.5) * 2.0 * PI;
  float el = (uv.y - 0.5) * PI;
  return vec3(cos(el) * cos(phi), sin(el), cos(el) * sin(phi));
}
// An orthonormal frame with z = n (rows: to local), for sampling around any direction.
mat3 frameAround(vec3 n) {
  vec3 t = normalize(abs(n.z) < 0.999 ? cross(vec3(0.0, 0.0, 1.0), n) : cross(vec3(1.0, 0.0, 0.0), n));
  return mat3(t, cross(n, t), n);
}
