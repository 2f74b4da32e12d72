// OpenPBR's fuzz lobe (Zeltner, Burley & Chiang 2022, MaterialX 1.39's fits), mirrors src/math/openpbr-fuzz.js.
// l, v in the local frame (n = z); roughness = fuzz_roughness, clamped to [0.01, 1] as MaterialX does.
#include "common.glsl"
#define FUZZ_ROUGHNESS_MIN 0.01
#define FUZZ_MU_MIN 1e-7

float albedoFuzzZeltner(float mu, float roughness) {
  float x = clamp(mu, FUZZ_MU_MIN, 1.0);
  float y = clamp(roughness, FUZZ_ROUGHNESS_MIN, 1.0);
  float s = y * (0.0206607 + 1.58491 * y) / (0.0379424 + y * (1.32227 + y));
  float m = y * (-0.193854 + y * (-1.14885 + y * (1.7932 - 0.95943 * y * y))) / (0.046391 + y);
  float o = y * (0.000654023 + (-0.0207818 + 0.119681 * y) * y) / (1.26264 + y * (-1.92021 + y));
  float z = (x - m) / s;
  return max(exp(-0.5 * z * z) / (s * sqrt(2.0 * PI)) + o, 0.0);
}

float ltcFuzzZeltner(vec3 l, vec3 v, float roughness) {
  float x = clamp(v.z, FUZZ_MU_MIN, 1.0);
  float y = clamp(roughness, FUZZ_ROUGHNESS_MIN, 1.0);
  float aInv = (2.58126 * x + 0.813703 * y) * y / (1.0 + 0.310327 * x * x + 2.60994 * x * y);
  float bInv = sqrt(1.0 - x) * (y - 1.0) * y * y * y / (0.0000254053 + 1.71228 * x - 1.71506 * x * y + 1.34174 * y * y);
  float sv = length(v.xy);
  vec2 c = sv > 0.0 ? v.xy / sv : vec2(1.0, 0.0);
  vec3 w = vec3(aInv * dot(l.xy, c) + bInv * l.z, aInv * (l.y * c.x - l.x * c.y), l.z);
  if (!(w.z > 0.0)) return 0.0;
  float len2 = dot(w, w);
  float k = aInv / len2;
  return w.z / PI * k * k;
}

float fuzzZeltner(vec3 l, vec3 v, float roughness) {
  if (!(l.z > 0.0 && v.z > 0.0)) return 0.0;
  return albedoFuzzZeltner(v.z, roughness) * ltcFuzzZeltner(l, v, roughness) / l.z;
}
