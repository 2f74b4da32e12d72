// A distant sphere light by the representative point (Karis 2013), mirrors src/math/lighting.js.
#include "common.glsl"
float sphereLightCLight(float radiance, float sinRadius) { return radiance * sinRadius * sinRadius; }

vec3 sphereLightRepresentativeDir(vec3 r, vec3 d, float sinRadius) {
  vec3 c = dot(d, r) * r - d;
  float len = length(c);
  float t = len > sinRadius ? sinRadius / len : 1.0;
  vec3 p = d + t * c;
  float pl = length(p);
  return pl > 0.0 ? p / pl : d;
}

float sphereLightNormalization(float alpha, float sinRadius) {
  float widened = min(alpha + 0.5 * sinRadius, 1.0);
  return widened > 0.0 ? min((alpha / widened) * (alpha / widened), 1.0) : 1.0;
}
