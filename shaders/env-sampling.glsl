// Directions drawn from an equirectangular map by its brightness, from the tables of src/lab/env-sampling.js: the
// marginal CDF over rows (uEnvMarginal), each row's conditional CDF (uEnvConditional) and the density per texel
// (uEnvPdf).
#include "env.glsl"

uniform sampler2D uEnvMarginal;
uniform sampler2D uEnvConditional;
uniform sampler2D uEnvPdf;

// Index of the first entry >= u in row `row` of a CDF texture (binary search).
int searchCdf(sampler2D cdf, int row, int count, float u) {
  int lo = 0;
  int hi = count - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (texelFetch(cdf, ivec2(mid, row), 0).r < u) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

// Where u lands between the CDF's previous entry and entry k: 0..1, so the point is continuous inside a texel.
float withinCdf(sampler2D cdf, int row, int k, float u) {
  float prev = k > 0 ? texelFetch(cdf, ivec2(k - 1, row), 0).r : 0.0;
  float cur = texelFetch(cdf, ivec2(k, row), 0).r;
  return cur > prev ? clamp((u - prev) / (cur - prev), 0.0, 1.0) : 0.5;
}

vec3 sampleEnvironmentMap(vec2 u) {
  ivec2 size = textureSize(uEnvConditional, 0);
  int j = searchCdf(uEnvMarginal, 0, size.y, u.x);
  float dv = withinCdf(uEnvMarginal, 0, j, u.x);
  int i = searchCdf(uEnvConditional, j, size.x, u.y);
  float du = withinCdf(uEnvConditional, j, i, u.y);
  return equirectDirection(vec2((float(i) + du) / float(size.x), (float(j) + dv) / float(size.y)));
}

// Density per steradian of sampleEnvironmentMap at direction d.
float environmentMapPdf(vec3 d) {
  ivec2 size = textureSize(uEnvPdf, 0);
  vec2 uv = equirectUv(d);
  ivec2 t = min(ivec2(uv * vec2(size)), size - 1);
  return texelFetch(uEnvPdf, t, 0).r / max(cos((uv.y - 0.5) * PI), 1e-6);
}
