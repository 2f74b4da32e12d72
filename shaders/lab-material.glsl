// The material lab's BRDF: the chosen specular lobe (brdf.glsl's F, D and V) with, under COMPENSATION_KULLA_CONTY or
// COMPENSATION_TURQUIN, its multiple scattering put back (multiple-scattering.glsl; the tables are GGX with
// height-correlated Smith's), plus the chosen diffuse term (DIFFUSE_*). SPECULAR_OFF / DIFFUSE_OFF show one layer
// alone. With MEASURED the BRDF is a measured table (measured.glsl, uMeasured), whole: its specular and diffuse are
// not apart, so specularBRDF is the table and diffuseBRDF 0; uAlpha is then the GGX fit's, for sampling only.
#ifdef MEASURED
#include "measured.glsl"
#else
#include "brdf.glsl"
#include "diffuse.glsl"
#endif
#if defined(COMPENSATION_KULLA_CONTY) || defined(COMPENSATION_TURQUIN)
#include "multiple-scattering.glsl"
#endif

uniform vec3 uF0;
uniform vec3 uDiffuseColor;
uniform float uAlpha;
uniform float uSigma;

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
#else
  vec3 f = microfacetBRDF(l, v, uAlpha, uF0);
#if defined(COMPENSATION_TURQUIN)
  f *= energyCompensationTurquin(F0_BOUNCES, 1.0 - albedoLossTableGGX(v.z, uAlpha).x);
#elif defined(COMPENSATION_KULLA_CONTY)
  f += multipleScatteringKullaConty(l.z, v.z, uAlpha) * fresnelBounces();
#endif
  return specularOn * f;
#endif
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
#else
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
#endif
}

vec3 brdfTotal(vec3 l, vec3 v) { return specularBRDF(l, v) + diffuseBRDF(l, v); }

// The talk's punctual light from direction l: pi f c_light (n·l), n·l clamped.
vec3 punctualRadiance(vec3 l, vec3 v, vec3 cLight) { return PI * brdfTotal(l, v) * cLight * max(l.z, 0.0); }
