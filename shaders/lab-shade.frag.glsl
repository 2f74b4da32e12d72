// The material lab: one orthographic unit sphere seen along -z (v = z), shaded by the chosen BRDF under the
// lights that are on. Each light is rendered by an approximation, or with REFERENCE by Monte Carlo batches
// whose running mean converges to the reflectance equation. Alpha is the sphere mask (1 on it, 0 off it).
// Switches: terms (brdf.glsl, DIFFUSE_*), lights (LIGHT_PUNCTUAL, LIGHT_SPHERE, LIGHT_ENV, LIGHT_AMBIENT),
// methods (ENV_MIRROR, ENV_IMPORTANCE, ENV_SPLIT_SUM; AREA_CENTRE; else the representative point).
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
uniform int uSamples;
uniform vec2 uJitter;
uniform sampler2D uPrevious;
uniform float uWeight;
out vec4 fragColor;

vec3 diffuseBRDF(vec3 l, vec3 v) {
  if (l.z <= 0.0 || v.z <= 0.0) return vec3(0.0);
#if defined(DIFFUSE_FRESNEL_WEIGHTED)
  return vec3(diffuseFresnelWeighted(l.z, v.z, uF0.r, uDiffuseColor.r), diffuseFresnelWeighted(l.z, v.z, uF0.g, uDiffuseColor.g),
              diffuseFresnelWeighted(l.z, v.z, uF0.b, uDiffuseColor.b));
#elif defined(DIFFUSE_ASHIKHMIN_SHIRLEY)
  return vec3(diffuseAshikhminShirley(l.z, v.z, uF0.r, uDiffuseColor.r), diffuseAshikhminShirley(l.z, v.z, uF0.g, uDiffuseColor.g),
              diffuseAshikhminShirley(l.z, v.z, uF0.b, uDiffuseColor.b));
#elif defined(DIFFUSE_OREN_NAYAR) || defined(DIFFUSE_OREN_NAYAR_QUALITATIVE)
  float d = sqrt(dot(l.xy, l.xy) * dot(v.xy, v.xy));
  float cosPhi = d > 1e-12 ? dot(l.xy, v.xy) / d : 0.0; // azimuth undefined along n, where the term does not need it
#ifdef DIFFUSE_OREN_NAYAR
  return uDiffuseColor * diffuseOrenNayar(l.z, v.z, cosPhi, uSigma, 1.0);
#else
  return uDiffuseColor * diffuseOrenNayarQualitative(l.z, v.z, cosPhi, uSigma, 1.0);
#endif
#else
  return uDiffuseColor * diffuseLambert(1.0);
#endif
}

vec3 brdfTotal(vec3 l, vec3 v) { return microfacetBRDF(l, v, uAlpha, uF0) + diffuseBRDF(l, v); }

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

// Per-pixel offset of the sample pattern (a hash), so neighbouring pixels do not share one pattern.
vec2 pixelHash(vec2 p) {
  vec3 q = fract(vec3(p.xyx) * vec3(0.1031, 0.1030, 0.0973));
  q += dot(q, q.yzx + 33.33);
  return fract((q.xx + q.yz) * q.zy);
}

// The reflectance equation against the environment: the specular lobe by GGX importance sampling
// (pdf D(m)(n·m)/(4 v·m)), the diffuse by cosine sampling (pdf (n·l)/pi), n samples each.
vec3 environmentSampled(mat3 toWorld, vec3 v, int n, vec2 shift) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec2 u = fract(hammersley(i, n) + shift);
    vec3 m = sampleGGXNormal(u, uAlpha);
    float vm = dot(v, m);
    vec3 l = 2.0 * vm * m - v;
    if (vm > 0.0 && l.z > 0.0) {
      float pdf = ndfGGXFromSin2(m.z, dot(m.xy, m.xy), uAlpha) * m.z / (4.0 * vm);
      sum += microfacetBRDF(l, v, uAlpha, uF0) * l.z / max(pdf, 1e-30) * envRadiance(toWorld * l, 0.0);
    }
    vec3 ld = sampleCosine(u);
    sum += diffuseBRDF(ld, v) * PI * envRadiance(toWorld * ld, 0.0);
  }
  return sum / float(n);
}

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

vec3 prefiltered(vec3 r, float alpha) {
  float level = sqrt(alpha) * uPrefilterLevels; // layers at perceptual roughness k/levels; level 0 is the map
  float k = min(floor(level), uPrefilterLevels - 1.0);
  float t = level - k;
  vec3 lo = k < 0.5 ? textureLod(uEnv, equirectUv(r), 0.0).rgb : texture(uPrefiltered, vec3(equirectUv(r), k - 1.0)).rgb;
  vec3 hi = texture(uPrefiltered, vec3(equirectUv(r), k)).rgb;
  return mix(lo, hi, t);
}

vec2 dfg(float nv) { return texture(uDfg, vec2(nv, sqrt(uAlpha))).rg; }

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
#else
  vec2 shift = vec2(0.0);
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
  Lo += PI * microfacetBRDF(lRep, v, uAlpha, uF0) * cLight * max(lRep.z, 0.0) * sphereLightNormalization(uAlpha, uSphereSin);
  Lo += PI * diffuseBRDF(d, v) * cLight * max(d.z, 0.0);
#endif
#endif

#if defined(LIGHT_ENV) || defined(LIGHT_AMBIENT)
#if defined(REFERENCE) || defined(ENV_IMPORTANCE)
  Lo += environmentSampled(toWorld, v, uSamples, shift);
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
  Lo += specular + uDiffuseColor * irradiance;
#endif
#endif

#ifdef REFERENCE
  Lo = mix(texelFetch(uPrevious, ivec2(gl_FragCoord.xy), 0).rgb, Lo, uWeight);
#endif
  fragColor = vec4(Lo, 1.0);
}
