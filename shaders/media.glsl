// Light in homogeneous media, mirrors src/math/media.js.
#include "common.glsl"
// A uniform number in [0, 1 - 2^-24] from 32 random bits: their top 24, which float32 holds exactly. All 32 divided
// by 2^32 round up to 1.0 for the top 128 values (float32 steps by 256 there), and the free flight -log(1 - u) would
// take log(0), which GLSL ES 3.00 leaves undefined (a NaN there stays in the running sum for good).
float uniformFromBits(uint bits) { return float(bits >> 8u) / 16777216.0; }
float transmittance(float sigma, float distance) { return exp(-max(sigma, 0.0) * max(distance, 0.0)); }
vec3 transmittance(vec3 sigma, float distance) { return exp(-max(sigma, vec3(0.0)) * max(distance, 0.0)); }
