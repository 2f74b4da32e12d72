// The reflectance equation by importance sampling, mirrors src/math/integrate.js: the same Hammersley points,
// the same GGX normal sampling, the same estimator V nl (v·m)/(n·m).
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

// The split-sum DFG term: (scale, bias) with ∫ f (n·l) dω = F0·scale + bias, mirrors dfgSplitSum.
vec2 dfgSplitSum(float mu, float alpha, int n) {
  float m0 = clamp(mu, 1e-6, 1.0);
  vec3 v = vec3(sqrt(max(sin2FromCos(m0), 0.0)), 0.0, m0);
  vec2 sum = vec2(0.0);
  for (int i = 0; i < n; i++) {
    vec3 m = sampleGGXNormal(hammersley(i, n), alpha);
    float vm = dot(v, m);
    if (vm <= 0.0) continue;
    vec3 l = 2.0 * vm * m - v;
    if (l.z <= 0.0) continue;
    float w = visibilitySmithGGXCorrelated(l.z, v.z, alpha) * l.z * vm / m.z;
    float fc = pow(1.0 - vm, 5.0);
    sum += vec2(1.0 - fc, fc) * w;
  }
  sum /= float(n);
  return sum / max(sum.x + sum.y, 1.0);
}

// Directional albedo with F = 1, mirrors albedoGGX: the split sum's scale + bias.
float albedoGGX(float mu, float alpha, int n) {
  vec2 ab = dfgSplitSum(mu, alpha, n);
  return ab.x + ab.y;
}

// Texture coordinates of (n·v, alpha) in the DFG table, mirrors dfgTableUv: texel centres edge to edge over
// (n·v)^0.4 and alpha^(1/3) (DFG_TABLE_SIZE and the warp are those of src/math/integrate.js)
#define DFG_TABLE_SIZE 64.0
vec2 dfgTableUv(float nv, float alpha) {
  vec2 x = pow(clamp(vec2(nv, alpha), 0.0, 1.0), vec2(0.4, 1.0 / 3.0));
  return (x * (DFG_TABLE_SIZE - 1.0) + 0.5) / DFG_TABLE_SIZE;
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
