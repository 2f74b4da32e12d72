// The material lab: one orthographic unit sphere seen along -z (v = z), shaded by the chosen BRDF under the
// lights that are on. Each light is rendered by an approximation, or with REFERENCE by Monte Carlo batches
// whose running mean converges to the reflectance equation. Alpha is the sphere mask (1 on it, 0 off it).
// Switches: terms (brdf.glsl, DIFFUSE_*), lights (LIGHT_PUNCTUAL, LIGHT_SPHERE, LIGHT_ENV, LIGHT_AMBIENT),
// methods (ENV_MIRROR, ENV_IMPORTANCE, ENV_SPLIT_SUM; AREA_CENTRE; else the representative point), and
// SPECULAR_OFF / DIFFUSE_OFF to see one layer alone. The approximations follow the chosen F, D and V: uDfg is the
// DFG table and uPrefiltered the map prefiltered for them; where a method has no form for the chosen diffuse term,
// irradiance × Lambert stands in (src/core/lab/lab-approximations.js says so on the page). With
// COMPENSATION_KULLA_CONTY or COMPENSATION_TURQUIN the specular lobe gets its multiple scattering back
// (multiple-scattering.glsl; the tables are GGX with height-correlated Smith's), in the reference and the methods.
// With MEASURED the BRDF is a measured table (measured.glsl, uMeasured), whole: its specular and diffuse are not
// apart, so specularBRDF is the table and diffuseBRDF 0; uAlpha is then the GGX fit's, for sampling only.
#include "brdf.glsl"
#include "diffuse.glsl"
#include "ndf-sampling.glsl"
#include "lighting.glsl"
#include "env.glsl"
#if defined(COMPENSATION_KULLA_CONTY) || defined(COMPENSATION_TURQUIN)
#include "multiple-scattering.glsl"
#endif
#ifdef MEASURED
#include "measured.glsl"
#endif

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

#ifdef F_ONE
#define F0_BOUNCES vec3(1.0)
#else
#define F0_BOUNCES uF0
#endif

#ifdef COMPENSATION_KULLA_CONTY
// Kulla & Conty's Fresnel factor of the multiple-scattering lobe for this material and roughness
vec3 fresnelBounces() { return fresnelMultipleScatteringKullaConty(fresnelAverage(F0_BOUNCES), averageAlbedoGGX(uAlpha)); }
#endif

// The specular lobe: single scattering, times Turquin's factor at v or plus Kulla & Conty's lobe.
vec3 specularBRDF(vec3 l, vec3 v) {
#ifdef MEASURED
  return measuredBRDF(vec3(0.0, 0.0, 1.0), l, v);
#endif
  vec3 f = microfacetBRDF(l, v, uAlpha, uF0);
#if defined(COMPENSATION_TURQUIN)
  f *= energyCompensationTurquin(F0_BOUNCES, 1.0 - albedoLossTableGGX(v.z, uAlpha).x);
#elif defined(COMPENSATION_KULLA_CONTY)
  f += multipleScatteringKullaConty(l.z, v.z, uAlpha) * fresnelBounces();
#endif
  return specularOn * f;
}

// cos of the azimuth between l and v about n = z; 0 where either lies along n (no term depends on it there)
float cosPhiBetween(vec3 l, vec3 v) {
  float d = sqrt(dot(l.xy, l.xy) * dot(v.xy, v.xy));
  return d > 1e-12 ? dot(l.xy, v.xy) / d : 0.0;
}

// The chosen diffuse term per channel, the colour passed in: Oren-Nayar's inter-reflection term goes as c², so
// it cannot be evaluated for c = 1 and scaled.
vec3 diffuseBRDF(vec3 l, vec3 v) {
#ifdef MEASURED
  return vec3(0.0); // in the table
#endif
  if (l.z <= 0.0 || v.z <= 0.0) return vec3(0.0);
  vec3 c = diffuseColor;
#if defined(DIFFUSE_FRESNEL_WEIGHTED)
  return vec3(diffuseFresnelWeighted(l.z, v.z, uF0.r, c.r), diffuseFresnelWeighted(l.z, v.z, uF0.g, c.g),
              diffuseFresnelWeighted(l.z, v.z, uF0.b, c.b));
#elif defined(DIFFUSE_ASHIKHMIN_SHIRLEY)
  return vec3(diffuseAshikhminShirley(l.z, v.z, uF0.r, c.r), diffuseAshikhminShirley(l.z, v.z, uF0.g, c.g),
              diffuseAshikhminShirley(l.z, v.z, uF0.b, c.b));
#elif defined(DIFFUSE_OREN_NAYAR)
  float cp = cosPhiBetween(l, v);
  return vec3(diffuseOrenNayar(l.z, v.z, cp, uSigma, c.r), diffuseOrenNayar(l.z, v.z, cp, uSigma, c.g),
              diffuseOrenNayar(l.z, v.z, cp, uSigma, c.b));
#elif defined(DIFFUSE_OREN_NAYAR_QUALITATIVE)
  float cp = cosPhiBetween(l, v);
  return vec3(diffuseOrenNayarQualitative(l.z, v.z, cp, uSigma, c.r),
              diffuseOrenNayarQualitative(l.z, v.z, cp, uSigma, c.g),
              diffuseOrenNayarQualitative(l.z, v.z, cp, uSigma, c.b));
#else
  return vec3(diffuseLambert(c.r), diffuseLambert(c.g), diffuseLambert(c.b));
#endif
}

vec3 brdfTotal(vec3 l, vec3 v) { return specularBRDF(l, v) + diffuseBRDF(l, v); }

// The talk's punctual light: pi f c_light (n·l), n·l clamped.
vec3 punctual(vec3 l, vec3 v, vec3 cLight) { return PI * brdfTotal(l, v) * cLight * max(l.z, 0.0); }

vec3 envMap(vec3 dWorld, float lod) { return uEnvIntensity * textureLod(uEnv, equirectUv(dWorld), lod).rgb; }

// All the light around the sphere: the map and the ambient radiance (what the reference integrates at once).
vec3 surroundRadiance(vec3 dWorld) {
  vec3 L = vec3(0.0);
#ifdef LIGHT_ENV
  L += envMap(dWorld, 0.0);
#endif
#ifdef LIGHT_AMBIENT
  L += uAmbient;
#endif
  return L;
}

#ifdef LIGHT_PUNCTUAL
vec3 punctualLight(mat3 toLocal, vec3 v) { return punctual(toLocal * uPunctualDir, v, uPunctualCLight); }
#endif

#if defined(LIGHT_SPHERE) && !defined(REFERENCE)
// The sphere light as a punctual light at its centre, or by the representative point (Karis 2013): the specular
// from the point of the disc nearest the reflected ray, the diffuse from the centre.
vec3 sphereLight(mat3 toLocal, vec3 v) {
  vec3 d = toLocal * uSphereDir;
  vec3 cLight = sphereLightCLight(1.0, uSphereSin) * uSphereRadiance;
#ifdef AREA_CENTRE
  return punctual(d, v, cLight);
#else
  vec3 lRep = sphereLightRepresentativeDir(reflect(-v, vec3(0.0, 0.0, 1.0)), d, uSphereSin);
  vec3 specular = PI * specularBRDF(lRep, v) * cLight * max(lRep.z, 0.0) * sphereLightNormalization(uAlpha, uSphereSin);
  return specular + PI * diffuseBRDF(d, v) * cLight * max(d.z, 0.0);
#endif
}
#endif

#if defined(REFERENCE) && defined(LIGHT_SPHERE)
// The sphere light by uniform samples of its cone: pdf 1/(2 pi (1 - cos theta_s)).
vec3 sphereLight(mat3 toLocal, vec3 v, int n, vec2 shift) {
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

#if defined(ENV_SPLIT_SUM) || defined(LIGHT_AMBIENT) && !defined(REFERENCE)
// The DFG table of the chosen D and V at (n·v, alpha) (dfgTableUv): (A, B) with ∫ f (n·l) dω = F0·A + B for
// Schlick's F, and A + B for F = 1 (the two parts of the split add back up to the albedo).
vec3 dfgAlbedo(float nv) {
  vec2 ab = texture(uDfg, dfgTableUv(nv, uAlpha)).rg;
#ifdef F_ONE
  vec3 single = vec3(ab.x + ab.y);
#else
  vec3 single = uF0 * ab.x + ab.y;
#endif
#ifdef COMPENSATION_TURQUIN
  single *= energyCompensationTurquin(F0_BOUNCES, 1.0 - albedoLossTableGGX(nv, uAlpha).x);
#endif
  return single;
}

// What Kulla & Conty's lobe adds under uniform light of radiance 1: F_ms (1 - E(n·v)) (its integral); under an
// environment it is applied to the irradiance, as the lobe is nearly flat in l (Fdez-Agüera 2019).
vec3 multipleAlbedo(float nv) {
#ifdef COMPENSATION_KULLA_CONTY
  return fresnelBounces() * albedoLossTableGGX(nv, uAlpha).x;
#else
  return vec3(0.0);
#endif
}
#endif

#ifdef ENV_SPLIT_SUM
// The map prefiltered with the chosen NDF's lobe: layers at perceptual roughness k/levels, level 0 the map itself.
vec3 prefiltered(vec3 r, float alpha) {
  float level = sqrt(alpha) * uPrefilterLevels;
  float k = min(floor(level), uPrefilterLevels - 1.0);
  float t = level - k;
  vec2 uv = equirectUv(r);
  vec3 lo = k < 0.5 ? textureLod(uEnv, uv, 0.0).rgb : texture(uPrefiltered, vec3(uv, k - 1.0)).rgb;
  vec3 hi = texture(uPrefiltered, vec3(uv, k)).rgb;
  return uEnvIntensity * mix(lo, hi, t);
}
#endif

#if defined(ENV_MIRROR) || defined(ENV_SPLIT_SUM)
// The environment by the mirror direction alone (F at n·v, the half vector of a mirror being n) or by the split
// sum; the diffuse by irradiance × Lambert whatever diffuse term is chosen (the form these methods have).
vec3 environmentLight(vec3 n, mat3 toWorld, vec3 v) {
  vec3 rWorld = reflect(-vec3(0.0, 0.0, 1.0), n);
#ifdef ENV_MIRROR
#ifdef F_ONE
  vec3 specular = envMap(rWorld, 0.0);
#else
  vec3 specular = fresnelSchlick(uF0, v.z) * envMap(rWorld, 0.0);
#endif
#else
  vec3 specular = prefiltered(rWorld, uAlpha) * dfgAlbedo(v.z);
#endif
  vec3 irradiance = uEnvIntensity * texture(uIrradiance, equirectUv(n)).rgb; // radiance of a white Lambertian surface
#ifdef ENV_SPLIT_SUM
  specular += multipleAlbedo(v.z) * irradiance;
#endif
  return specularOn * specular + diffuseColor * irradiance;
}
#endif

#if defined(ENV_IMPORTANCE) && defined(MEASURED)
// A table's f under the map: one direction from the fitted lobe and one by cosine per sample, each weighted by
// the balance heuristic f (n·l) L / (pdf_lobe + pdf_cosine), as the table has no diffuse part to sample alone.
vec3 balancedSample(vec3 l, vec3 v, mat3 toWorld) {
  if (l.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float pdf = reflectedPdf(h, dot(v, h), uAlpha) + l.z / PI;
  return specularBRDF(l, v) * l.z * envMap(toWorld * l, 0.0) / max(pdf, 1e-30);
}

vec3 environmentLight(vec3 n, mat3 toWorld, vec3 v) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < uSamples; i++) {
    vec2 u = hammersley(i, uSamples); // the same pattern on every pixel, as a renderer would use it
    vec3 m = sampleLobeNormal(u, uAlpha);
    sum += balancedSample(2.0 * dot(v, m) * m - v, v, toWorld) + balancedSample(sampleCosine(u), v, toWorld);
  }
  return sum / float(uSamples);
}
#elif defined(ENV_IMPORTANCE)
// The reflectance equation against the map as a renderer would sample it: l = reflect(v, m) with m from the
// lobe (ndf-sampling.glsl), the diffuse by cosine sampling (pdf (n·l)/pi), n samples each, every term evaluated.
vec3 environmentLight(vec3 n, mat3 toWorld, vec3 v) {
  vec3 sum = vec3(0.0);
  int count = uSamples;
  for (int i = 0; i < count; i++) {
    vec2 u = hammersley(i, count); // the same pattern on every pixel, as a renderer would use it
    vec3 m = sampleLobeNormal(u, uAlpha);
    float vm = dot(v, m);
    vec3 l = 2.0 * vm * m - v;
    if (vm > 0.0 && l.z > 0.0) {
      sum += specularBRDF(l, v) * l.z / max(reflectedPdf(m, vm, uAlpha), 1e-30) * envMap(toWorld * l, 0.0);
    }
    vec3 ld = sampleCosine(u);
    sum += diffuseBRDF(ld, v) * PI * envMap(toWorld * ld, 0.0);
  }
  return sum / float(count);
}
#endif

#if defined(LIGHT_AMBIENT) && !defined(REFERENCE)
// Uniform radiance: the specular albedo from the DFG table, the diffuse albedo c of Lambert (the form it has).
vec3 ambientLight(vec3 v) { return uAmbient * (specularOn * (dfgAlbedo(v.z) + multipleAlbedo(v.z)) + diffuseColor); }
#endif

#ifdef REFERENCE
// Per-pixel offset of the sample pattern (a hash), so neighbouring pixels do not share one pattern.
vec2 pixelHash(vec2 p) {
  vec3 q = fract(vec3(p.xyx) * vec3(0.1031, 0.1030, 0.0973));
  q += dot(q, q.yzx + 33.33);
  return fract((q.xx + q.yz) * q.zy);
}

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

// One sample from each of three strategies (the lobe, cosine, the map's brightness), weighted by the balance
// heuristic: each contributes f (n·l) L / (sum of the three densities at its direction).
vec3 referenceSample(vec3 l, vec3 v, mat3 toWorld) {
  if (l.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float pdf = reflectedPdf(h, dot(v, h), uAlpha) + l.z / PI;
  vec3 dWorld = toWorld * l;
  if (uEnvSampling) pdf += environmentMapPdf(dWorld);
  return brdfTotal(l, v) * l.z * surroundRadiance(dWorld) / max(pdf, 1e-30);
}

// The environment and ambient light together, by multiple importance sampling.
vec3 surroundReference(mat3 toWorld, mat3 toLocal, vec3 v, int n, vec2 shift) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec2 u = fract(hammersley(i, n) + shift);
    vec3 m = sampleLobeNormal(u, uAlpha);
    sum += referenceSample(2.0 * dot(v, m) * m - v, v, toWorld);
    sum += referenceSample(sampleCosine(u.yx), v, toWorld);
    if (uEnvSampling) sum += referenceSample(toLocal * sampleEnvironmentMap(u), v, toWorld);
  }
  return sum / float(n);
}
#endif

// Each light on, by its method (or by Monte Carlo with REFERENCE), summed.
void main() {
  vec2 p = (2.0 * gl_FragCoord.xy / uSize - 1.0) * uExtent;
  float r2 = dot(p, p);
  if (r2 >= 1.0) {
    fragColor = vec4(surroundRadiance(normalize(vec3(0.5 * p, -1.0))), 0.0);
    return;
  }
  vec3 n = vec3(p, sqrt(1.0 - r2));
  mat3 toWorld = frameAround(n);
  mat3 toLocal = transpose(toWorld);
  vec3 v = toLocal * vec3(0.0, 0.0, 1.0);
  vec3 Lo = vec3(0.0);
#ifdef LIGHT_PUNCTUAL
  Lo += punctualLight(toLocal, v);
#endif
#ifdef REFERENCE
  vec2 shift = fract(uJitter + pixelHash(gl_FragCoord.xy));
#ifdef LIGHT_SPHERE
  Lo += sphereLight(toLocal, v, uSamples, shift);
#endif
#if defined(LIGHT_ENV) || defined(LIGHT_AMBIENT)
  Lo += surroundReference(toWorld, toLocal, v, uSamples, shift);
#endif
  Lo = mix(texelFetch(uPrevious, ivec2(gl_FragCoord.xy), 0).rgb, Lo, uWeight);
#else
#ifdef LIGHT_SPHERE
  Lo += sphereLight(toLocal, v);
#endif
#if defined(ENV_MIRROR) || defined(ENV_SPLIT_SUM) || defined(ENV_IMPORTANCE)
  Lo += environmentLight(n, toWorld, v);
#endif
#ifdef LIGHT_AMBIENT
  Lo += ambientLight(v);
#endif
#endif
  fragColor = vec4(Lo, 1.0);
}
