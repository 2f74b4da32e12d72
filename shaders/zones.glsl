// The talk's Fresnel zones, mirrors src/math/zones.js.
#include "common.glsl"
float fresnelZone(float cosTheta) {
  float c = saturate(cosTheta);
  return c > 0.70710678118654757 ? 0.0 : c > 0.25881904510252074 ? 1.0 : 2.0;
}
