// The material lab's BRDF when it is the user's whole BRDF: src/lab/lab-renderer.js puts this chunk in place of
// measured.glsl, since lab-material.glsl's MEASURED path is the one for a BRDF that is whole (not apart into a
// specular lobe and a diffuse term) and reads it through measuredBRDF(n, l, v), n = (0, 0, 1) there. The user's
// customBRDF(l, v) is in the local frame too (custom-brdf.glsl, src/core/custom/assemble.js writes it); 0 at and
// below the horizon, as every BRDF of the app.
#include "custom-brdf.glsl"

vec3 measuredBRDF(vec3 n, vec3 l, vec3 v) {
  if (dot(n, l) <= 0.0 || dot(n, v) <= 0.0) return vec3(0.0);
  return customBRDF(l, v);
}
