// The material lab: one orthographic unit sphere seen along -z (v = z), shaded by the chosen BRDF under the
// lights that are on. Each light is rendered by an approximation, or with REFERENCE by Monte Carlo batches
// whose running mean converges to the reflectance equation. Alpha is the sphere mask (1 on it, 0 off it).
// Switches: terms (brdf.glsl, DIFFUSE_*), lights (LIGHT_PUNCTUAL, LIGHT_SPHERE, LIGHT_ENV, LIGHT_AMBIENT),
// methods (ENV_MIRROR, ENV_IMPORTANCE, ENV_SPLIT_SUM; AREA_CENTRE; else the representative point), and
// SPECULAR_OFF / DIFFUSE_OFF to see one layer alone.
#include "brdf.glsl"
#include "diffuse.glsl"
#include "integrate.glsl"
#include "lighting.glsl"
#include "env.glsl"

uniform vec2 uSize;
uniform float uExtent;
uniform vec3 uF0;
uniform vec3 uDiffuseColor;
uniform float uAlpha;
uniform float uSigma;
uniform vec3 uPunctualDir;
uniform vec3 uPunctualCLight;
uniform vec3 uSphereDir;
uniform float uSphereSin;
uniform vec3 uSphereRadiance;
uniform sampler2D uEnv;
uniform float uEnvIntensity;
uniform vec3 uAmbient;
uniform sampler2DArray uPrefiltered;
uniform float uPrefilterLevels;
uniform sampler2D uIrradiance;
uniform sampler2D uDfg;
uniform sampler2D uEnvMarginal;    // environment sampling tables (src/core/lab/env-sampling.js)
uniform sampler2D uEnvConditional;
uniform sampler2D uEnvPdf;
uniform bool uEnvSampling;
uniform int uSamples;
uniform vec2 uJitter;
uniform sampler2D uPrevious;
uniform float uWeight;
out vec4 fragColor;

#ifdef SPECULAR_OFF
const float specularOn = 0.0;
#else
const float specularOn = 1.0;
#endif
#ifdef DIFFUSE_OFF
const vec3 diffuseColor = vec3(0.0);
#else
#define diffuseColor uDiffuseColor
#endif

vec3 specularBRDF(vec3 l, vec3 v) { return specularOn * microfacetBRDF(l, v, uAlpha, uF0); }

vec3 diffuseBRDF(vec3 l, vec3 v) {
  if (l.z <= 0.0 || v.z <= 0.0) return vec3(0.0);
#if defined(DIFFUSE_FRESNEL_WEIGHTED)
  return vec3(diffuseFresnelWeighted(l.z, v.z, uF0.r, diffuseColor.r), diffuseFresnelWeighted(l.z, v.z, uF0.g, diffuseColor.g),
              diffuseFresnelWeighted(l.z, v.z, uF0.b, diffuseColor.b));
#elif defined(DIFFUSE_ASHIKHMIN_SHIRLEY)
  return vec3(diffuseAshikhminShirley(l.z, v.z, uF0.r, diffuseColor.r), diffuseAshikhminShirley(l.z, v.z, uF0.g, diffuseColor.g),
              diffuseAshikhminShirley(l.z, v.z, uF0.b, diffuseColor.b));
#elif defined(DIFFUSE_OREN_NAYAR) || defined(DIFFUSE_OREN_NAYAR_QUALITATIVE)
  float d = sqrt(dot(l.xy, l.xy) * dot(v.xy, v.xy));
  float cosPhi = d > 1e-12 ? dot(l.xy, v.xy) / d : 0.0; // azimuth undefined along n, where the term does not need it
#ifdef DIFFUSE_OREN_NAYAR
  return diffuseColor * diffuseOrenNayar(l.z, v.z, cosPhi, uSigma, 1.0);
#else
  return diffuseColor * diffuseOrenNayarQualitative(l.z, v.z, cosPhi, uSigma, 1.0);
#endif
#else
  return diffuseColor * diffuseLambert(1.0);
#endif
}

vec3 brdfTotal(vec3 l, vec3 v) { return specularBRDF(l, v) + diffuseBRDF(l, v); }

// The talk's punctual light: pi f c_light (n·l), n·l clamped.
vec3 punctual(vec3 l, vec3 v, vec3 cLight) { return PI * brdfTotal(l, v) * cLight * max(l.z, 0.0); }

vec3 envRadiance(vec3 dWorld, float lod) {
  vec3 L = vec3(0.0);
#ifdef LIGHT_ENV
  L += uEnvIntensity * textureLod(uEnv, equirectUv(dWorld), lod).rgb;
#endif
#ifdef LIGHT_AMBIENT
  L += uAmbient;
#endif
  return L;
}

#ifdef REFERENCE
// Per-pixel offset of the sample pattern (a hash), so neighbouring pixels do not share one pattern.
vec2 pixelHash(vec2 p) {
  vec3 q = fract(vec3(p.xyx) * vec3(0.1031, 0.1030, 0.0973));
  q += dot(q, q.yzx + 33.33);
  return fract((q.xx + q.yz) * q.zy);
}
#endif

#ifdef ENV_IMPORTANCE
// The reflectance equation against the environment as a renderer would sample it: the specular lobe by GGX
// importance sampling (pdf D(m)(n·m)/(4 v·m)), the diffuse by cosine sampling (pdf (n·l)/pi), n samples each.
vec3 environmentSampled(mat3 toWorld, vec3 v, int n) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec2 u = hammersley(i, n); // the same pattern on every pixel, as a renderer would use it
    vec3 m = sampleGGXNormal(u, uAlpha);
    float vm = dot(v, m);
    vec3 l = 2.0 * vm * m - v;
    if (vm > 0.0 && l.z > 0.0) {
      float pdf = ndfGGXFromSin2(m.z, dot(m.xy, m.xy), uAlpha) * m.z / (4.0 * vm);
      sum += specularBRDF(l, v) * l.z / max(pdf, 1e-30) * envRadiance(toWorld * l, 0.0);
    }
    vec3 ld = sampleCosine(u);
    sum += diffuseBRDF(ld, v) * PI * envRadiance(toWorld * ld, 0.0);
  }
  return sum / float(n);
}
#endif

#ifdef REFERENCE
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

// One sample from each of three strategies (GGX lobe, cosine, the map's brightness), weighted by the balance
// heuristic: each contributes f (n·l) L / (sum of the three densities at its direction).
vec3 referenceSample(vec3 l, vec3 v, mat3 toWorld) {
  if (l.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float vh = dot(v, h);
  float pdf = (vh > 0.0 ? ndfGGXFromSin2(h.z, dot(h.xy, h.xy), uAlpha) * h.z / (4.0 * vh) : 0.0) + l.z / PI;
  vec3 dWorld = toWorld * l;
  if (uEnvSampling) pdf += environmentMapPdf(dWorld);
  return brdfTotal(l, v) * l.z * envRadiance(dWorld, 0.0) / max(pdf, 1e-30);
}

vec3 environmentReference(mat3 toWorld, mat3 toLocal, vec3 v, int n, vec2 shift) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec2 u = fract(hammersley(i, n) + shift);
    vec3 m = sampleGGXNormal(u, uAlpha);
    sum += referenceSample(2.0 * dot(v, m) * m - v, v, toWorld);
    sum += referenceSample(sampleCosine(u.yx), v, toWorld);
    if (uEnvSampling) sum += referenceSample(toLocal * sampleEnvironmentMap(u), v, toWorld);
  }
  return sum / float(n);
}
#endif

#if defined(REFERENCE) && defined(LIGHT_SPHERE)
// The sphere light by uniform samples of its cone: pdf 1/(2 pi (1 - cos theta_s)).
vec3 sphereSampled(mat3 toLocal, vec3 v, int n, vec2 shift) {
  float cosMax = sqrt(max(1.0 - uSphereSin * uSphereSin, 0.0));
  mat3 coneToWorld = frameAround(uSphereDir);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec3 l = toLocal * (coneToWorld * sampleCone(fract(hammersley(i, n) + shift), cosMax));
    sum += brdfTotal(l, v) * max(l.z, 0.0);
  }
  return sum * uSphereRadiance * (2.0 * PI * (1.0 - cosMax)) / float(n);
}
#endif

#ifdef ENV_SPLIT_SUM
vec3 prefiltered(vec3 r, float alpha) {
  float level = sqrt(alpha) * uPrefilterLevels; // layers at perceptual roughness k/levels; level 0 is the map
  float k = min(floor(level), uPrefilterLevels - 1.0);
  float t = level - k;
  vec3 lo = k < 0.5 ? textureLod(uEnv, equirectUv(r), 0.0).rgb : texture(uPrefiltered, vec3(equirectUv(r), k - 1.0)).rgb;
  vec3 hi = texture(uPrefiltered, vec3(equirectUv(r), k)).rgb;
  return mix(lo, hi, t);
}

#endif

#if defined(ENV_SPLIT_SUM) || defined(LIGHT_AMBIENT)
vec2 dfg(float nv) { return texture(uDfg, vec2(nv, sqrt(uAlpha))).rg; }
#endif

void main() {
  vec2 p = (2.0 * gl_FragCoord.xy / uSize - 1.0) * uExtent;
  float r2 = dot(p, p);
  if (r2 >= 1.0) {
    vec3 behind = normalize(vec3(0.5 * p, -1.0));
    fragColor = vec4(envRadiance(behind, 0.0), 0.0);
    return;
  }
  vec3 n = vec3(p, sqrt(1.0 - r2));
  mat3 toWorld = frameAround(n);
  mat3 toLocal = transpose(toWorld);
  vec3 v = toLocal * vec3(0.0, 0.0, 1.0);
  vec3 Lo = vec3(0.0);
#ifdef REFERENCE
  vec2 shift = fract(uJitter + pixelHash(gl_FragCoord.xy));
#endif

#ifdef LIGHT_PUNCTUAL
  Lo += punctual(toLocal * uPunctualDir, v, uPunctualCLight);
#endif

#ifdef LIGHT_SPHERE
  vec3 d = toLocal * uSphereDir;
#if defined(REFERENCE)
  Lo += sphereSampled(toLocal, v, uSamples, shift);
#elif defined(AREA_CENTRE)
  Lo += punctual(d, v, sphereLightCLight(1.0, uSphereSin) * uSphereRadiance);
#else
  vec3 cLight = sphereLightCLight(1.0, uSphereSin) * uSphereRadiance;
  vec3 lRep = sphereLightRepresentativeDir(reflect(-v, vec3(0.0, 0.0, 1.0)), d, uSphereSin);
  Lo += PI * specularBRDF(lRep, v) * cLight * max(lRep.z, 0.0) * sphereLightNormalization(uAlpha, uSphereSin);
  Lo += PI * diffuseBRDF(d, v) * cLight * max(d.z, 0.0);
#endif
#endif

#if defined(LIGHT_ENV) || defined(LIGHT_AMBIENT)
#if defined(REFERENCE)
  Lo += environmentReference(toWorld, toLocal, v, uSamples, shift);
#elif defined(ENV_IMPORTANCE)
  Lo += environmentSampled(toWorld, v, uSamples);
#else
  vec3 rWorld = reflect(-vec3(0.0, 0.0, 1.0), n);
  vec3 irradiance = vec3(0.0); // mean radiance seen by a white Lambertian surface facing n
  vec3 specular = vec3(0.0);
#ifdef LIGHT_ENV
#if defined(ENV_MIRROR)
  specular += uEnvIntensity * fresnelSchlick(uF0, v.z) * textureLod(uEnv, equirectUv(rWorld), 0.0).rgb;
  irradiance += uEnvIntensity * texture(uIrradiance, equirectUv(n)).rgb;
#elif defined(ENV_SPLIT_SUM)
  vec2 ab = dfg(v.z);
  specular += uEnvIntensity * prefiltered(rWorld, uAlpha) * (uF0 * ab.x + ab.y);
  irradiance += uEnvIntensity * texture(uIrradiance, equirectUv(n)).rgb;
#endif
#endif
#ifdef LIGHT_AMBIENT
  vec2 abAmbient = dfg(v.z);
  specular += uAmbient * (uF0 * abAmbient.x + abAmbient.y);
  irradiance += uAmbient;
#endif
  Lo += specularOn * specular + diffuseColor * irradiance;
#endif
#endif

#ifdef REFERENCE
  Lo = mix(texelFetch(uPrevious, ivec2(gl_FragCoord.xy), 0).rgb, Lo, uWeight);
#endif
  fragColor = vec4(Lo, 1.0);
}
