// Environment maps: the equirectangular layout of three.js (y up), mirrors equirectUv/equirectDirection of
// src/math/lighting.js.
#include "common.glsl"
// GLSL ES 3.00 leaves atan(0, 0) undefined (llvmpipe gave u = 0.875 at the poles): u = 1/2 there, as JS's atan2(0, 0)
// = 0 gives. The elevation by atan of y over the horizontal length, not asin(y): GPUs' asin may be accurate to only
// ~4e-4 (llvmpipe's), their atan to ~2e-5.
vec2 equirectUv(vec3 d) {
  float horizontal = length(d.xz);
  if (horizontal == 0.0) return vec2(0.5, d.y > 0.0 ? 1.0 : d.y < 0.0 ? 0.0 : 0.5);
  return vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, atan(d.y, horizontal) / PI + 0.5);
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
