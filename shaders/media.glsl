// Light in homogeneous media, mirrors src/math/media.js.
#include "common.glsl"
float transmittance(float sigma, float distance) { return exp(-max(sigma, 0.0) * max(distance, 0.0)); }
vec3 transmittance(vec3 sigma, float distance) { return exp(-max(sigma, vec3(0.0)) * max(distance, 0.0)); }
