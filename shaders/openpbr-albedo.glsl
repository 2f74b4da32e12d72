// OpenPBR's dielectric albedo table E(μ, α, η) and the dielectric Fresnel's hemispherical average, mirrors
// src/math/openpbr-albedo.js: the float64 table (src/math/openpbr-albedo.data.js, 64 × 128 RGBA float, bound as
// uOpenPbrAlbedo by whoever draws) read by the same trilinear rule with texelFetch, so the two agree node for node.
#include "fresnel.glsl"
uniform sampler2D uOpenPbrAlbedo;
#define OPENPBR_ALBEDO_NODES 32

float openPbrAlbedoNode(int i, int j, int k) {
  int block = k / 4;
  ivec2 at = ivec2(i + OPENPBR_ALBEDO_NODES * (block - 2 * (block / 2)), j + OPENPBR_ALBEDO_NODES * (block / 2));
  vec4 t = texelFetch(uOpenPbrAlbedo, at, 0);
  int c = k - 4 * block;
  return c == 0 ? t.r : c == 1 ? t.g : c == 2 ? t.b : t.a;
}

float openPbrAlbedoBilinear(int i, int j, int k, vec2 f) {
  float lo = mix(openPbrAlbedoNode(i, j, k), openPbrAlbedoNode(i + 1, j, k), f.x);
  float hi = mix(openPbrAlbedoNode(i, j + 1, k), openPbrAlbedoNode(i + 1, j + 1, k), f.x);
  return lo + (hi - lo) * f.y;
}

float albedoAxisR(float eta) {
  float e = max(eta, 1.0);
  return sqrt((e - 1.0) / (e + 1.0));
}

float openPbrDielectricAlbedo(float mu, float alpha, float eta) {
  float n = float(OPENPBR_ALBEDO_NODES - 1);
  vec3 x = vec3(pow(max(mu, 0.0), 1.0 / 3.0), pow(max(alpha, 0.0), 1.0 / 3.0), albedoAxisR(eta));
  x = clamp(x, 0.0, 1.0) * n;
  ivec3 i = min(ivec3(floor(x)), ivec3(OPENPBR_ALBEDO_NODES - 2));
  vec3 f = x - vec3(i);
  float e0 = openPbrAlbedoBilinear(i.x, i.y, i.z, f.xy);
  return e0 + (openPbrAlbedoBilinear(i.x, i.y, i.z + 1, f.xy) - e0) * f.z;
}

// 2∫F μ dμ = 4∫F(s²) s³ ds by the 16-point Gauss–Legendre rule in s, nodes ±x on [-1, 1] (the JS twin's rule)
const float GL16_X[8] = float[8](0.9894009349916499, 0.9445750230732326, 0.8656312023878318, 0.755404408355003,
  0.6178762444026438, 0.45801677765722737, 0.2816035507792589, 0.09501250983763744);
const float GL16_W[8] = float[8](0.027152459411754058, 0.062253523938647776, 0.0951585116824929,
  0.12462897125553395, 0.14959598881657682, 0.16915651939500256, 0.1826034150449236, 0.18945061045506847);
float fresnelDielectricAverage(float eta) {
  float sum = 0.0;
  for (int i = 0; i < 8; i++) {
    float s0 = 0.5 * (1.0 + GL16_X[i]);
    float s1 = 0.5 * (1.0 - GL16_X[i]);
    float f0 = fresnelDielectric(s0 * s0, eta) * s0 * s0 * s0;
    sum += 2.0 * GL16_W[i] * (f0 + fresnelDielectric(s1 * s1, eta) * s1 * s1 * s1);
  }
  return sum;
}
