// The material lab's BRDF: the chosen specular lobe (brdf.glsl's F, D and V) with, under COMPENSATION_KULLA_CONTY or
// COMPENSATION_TURQUIN, its multiple scattering put back (multiple-scattering.glsl; the tables are GGX with
// height-correlated Smith's), plus the chosen diffuse term (DIFFUSE_*: diffuse-term.glsl, shared with the spheres).
// SPECULAR_OFF / DIFFUSE_OFF show one layer alone. With MEASURED the BRDF is a measured table (measured.glsl,
// uMeasured), whole: its specular and diffuse are not apart, so specularBRDF is the table and diffuseBRDF 0; uAlpha
// is then the GGX fit's, for sampling only; with OPENPBR too the whole BRDF is OpenPBR Surface's (lab-openpbr.glsl).
#if defined(MEASURED) && defined(OPENPBR)
#include "lab-openpbr.glsl"
#elif defined(MEASURED)
#include "measured.glsl"
#else
#include "brdf.glsl"
#include "diffuse-term.glsl"
#endif
#if defined(COMPENSATION_KULLA_CONTY) || defined(COMPENSATION_TURQUIN)
#include "multiple-scattering.glsl"
#endif

uniform vec3 uF0;
uniform vec3 uDiffuse;
uniform float uAlpha;
uniform float uSigma;
#include "lab-anisotropy.glsl"

#ifdef SPECULAR_OFF
const float specularOn = 0.0;
#else
const float specularOn = 1.0;
#endif
#ifdef DIFFUSE_OFF
const vec3 diffuseColor = vec3(0.0);
#else
#define diffuseColor uDiffuse
#endif

#ifdef F_ONE
#define F0_BOUNCES vec3(1.0)
#else
#define F0_BOUNCES uF0
#endif

#ifdef COMPENSATION_KULLA_CONTY
// Kulla & Conty's Fresnel factor of the multiple-scattering lobe for this material and roughness
vec3 fresnelBounces() {
  return fresnelMultipleScatteringKullaConty(fresnelAverage(F0_BOUNCES), averageAlbedoGGX(uAlpha));
}
#endif

// The specular lobe: single scattering, times Turquin's factor at v or plus Kulla & Conty's lobe.
vec3 specularBRDF(vec3 l, vec3 v) {
#ifdef MEASURED
  return measuredBRDF(vec3(0.0, 0.0, 1.0), l, v);
#else
  vec3 f = lobeBRDF(l, v, uF0);
#if defined(COMPENSATION_TURQUIN)
  f *= energyCompensationTurquin(F0_BOUNCES, 1.0 - albedoLossTableGGX(v.z, uAlpha).x);
#elif defined(COMPENSATION_KULLA_CONTY)
  f += multipleScatteringKullaConty(l.z, v.z, uAlpha) * fresnelBounces();
#endif
  return specularOn * f;
#endif
}

// The chosen diffuse term (diffuse-term.glsl), per channel with the colour passed in.
vec3 diffuseBRDF(vec3 l, vec3 v) {
#ifdef MEASURED
  return vec3(0.0); // in the table
#else
  return diffuseTerm(l, v, diffuseColor, uF0, uSigma);
#endif
}

vec3 brdfTotal(vec3 l, vec3 v) { return specularBRDF(l, v) + diffuseBRDF(l, v); }

// The talk's punctual light from direction l: pi f c_light (n·l), n·l clamped.
vec3 punctualRadiance(vec3 l, vec3 v, vec3 cLight) { return PI * brdfTotal(l, v) * cLight * max(l.z, 0.0); }
