// Sampling for the reflectance equation, mirrors src/math/integrate.js: the same Hammersley points, the same GGX
// and Beckmann normal sampling, the cosine and cone samplers; and where the split sum's table keeps (n·v, alpha)
// (the table itself is the float64 quadrature dfgSplitSum, made in JS).
#include "visibility.glsl"

vec2 hammersley(int i, int n) {
  uint bits = uint(i);
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return vec2((float(i) + 0.5) / float(n), float(bits) * 2.3283064365386963e-10);
}

vec3 sampleGGXNormal(vec2 u, float alpha) {
  float a = clampAlpha(alpha);
  float t2 = a * a * u.x / (1.0 - u.x);
  float c = inversesqrt(1.0 + t2);
  float s = sqrt(t2) * c;
  float phi = 2.0 * PI * u.y;
  return vec3(s * cos(phi), s * sin(phi), c);
}

// mirrors sampleBeckmannNormal: tan² = -alpha² ln(1 - u.x), with ln(1 - x) kept precise for small x
vec3 sampleBeckmannNormal(vec2 u, float alpha) {
  float a = clampAlpha(alpha);
  float t2 = -a * a * log1pSmall(-u.x);
  float c = inversesqrt(1.0 + t2);
  float s = sqrt(t2) * c;
  float phi = 2.0 * PI * u.y;
  return vec3(s * cos(phi), s * sin(phi), c);
}

// Texture coordinates of (n·v, alpha) in the DFG table, mirrors dfgTableUv (see there for the layout)
#define DFG_TABLE_SIZE 72.0
vec2 dfgTableUv(float nv, float alpha) {
  float mu = clamp(nv, 0.0, 1.0);
  float a = clamp(alpha, 0.0, 1.0);
  float k = 4.0 * max(a, ALPHA_MIN);
  float x = (sqrt(mu) + 0.5 * mu / (mu + k)) / (1.0 + 0.5 / (1.0 + k));
  return (vec2(x, pow(a, 1.0 / 3.0)) * (DFG_TABLE_SIZE - 1.0) + 0.5) / DFG_TABLE_SIZE;
}

vec3 sampleCosine(vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0 * PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
}

vec3 sampleCone(vec2 u, float cosMax) {
  float c = 1.0 - u.x * (1.0 - cosMax);
  float s = sqrt(max(sin2FromCos(c), 0.0));
  float phi = 2.0 * PI * u.y;
  return vec3(s * cos(phi), s * sin(phi), c);
}
