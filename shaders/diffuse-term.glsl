// The chosen diffuse term f_d(l, v) in the local frame (n = z), in 1/sr: DIFFUSE_* of
// src/math/catalogue/diffuse-terms.js picks one of diffuse.glsl. Evaluated per channel, the colour passed in:
// Oren-Nayar's inter-reflection term goes as c², so it cannot be evaluated for c = 1 and scaled. 0 at and below
// the horizon. Without a DIFFUSE_* switch there is no diffuseTerm and DIFFUSE_TERM_NONE is defined: a host whose
// diffuse layer is optional (brdf-sphere.frag.glsl) reads it; a host that needs a term can #error on it.
// DIFFUSE_CUSTOM: the user's customDiffuse(cdiff, l, v, alpha) (issue 13; its chunk custom-diffuse.glsl is written
// by src/core/custom/assemble.js), whole, its α the σ the others read (radians, as the checks' references take it).
#if defined(DIFFUSE_LAMBERT)
#include "diffuse.glsl"
float diffuseTermChannel(float nl, float nv, float cosPhi, float c, float f0, float sigma) {
  return diffuseLambert(c);
}
#elif defined(DIFFUSE_FRESNEL_WEIGHTED)
#include "diffuse.glsl"
float diffuseTermChannel(float nl, float nv, float cosPhi, float c, float f0, float sigma) {
  return diffuseFresnelWeighted(nl, nv, f0, c);
}
#elif defined(DIFFUSE_ASHIKHMIN_SHIRLEY)
#include "diffuse.glsl"
float diffuseTermChannel(float nl, float nv, float cosPhi, float c, float f0, float sigma) {
  return diffuseAshikhminShirley(nl, nv, f0, c);
}
#elif defined(DIFFUSE_OREN_NAYAR)
#include "diffuse.glsl"
float diffuseTermChannel(float nl, float nv, float cosPhi, float c, float f0, float sigma) {
  return diffuseOrenNayar(nl, nv, cosPhi, sigma, c);
}
#elif defined(DIFFUSE_OREN_NAYAR_QUALITATIVE)
#include "diffuse.glsl"
float diffuseTermChannel(float nl, float nv, float cosPhi, float c, float f0, float sigma) {
  return diffuseOrenNayarQualitative(nl, nv, cosPhi, sigma, c);
}
#elif defined(DIFFUSE_CUSTOM)
#include "custom-diffuse.glsl"
#else
#define DIFFUSE_TERM_NONE
#endif

#if defined(DIFFUSE_CUSTOM)
vec3 diffuseTerm(vec3 l, vec3 v, vec3 cdiff, vec3 f0, float sigma) {
  if (!(l.z > 0.0 && v.z > 0.0)) return vec3(0.0);
  return customDiffuse(cdiff, l, v, sigma);
}
#elif !defined(DIFFUSE_TERM_NONE)
vec3 diffuseTerm(vec3 l, vec3 v, vec3 cdiff, vec3 f0, float sigma) {
  if (!(l.z > 0.0 && v.z > 0.0)) return vec3(0.0);
  float cp = cosPhiDiff(l, v);
  return vec3(diffuseTermChannel(l.z, v.z, cp, cdiff.r, f0.r, sigma),
              diffuseTermChannel(l.z, v.z, cp, cdiff.g, f0.g, sigma),
              diffuseTermChannel(l.z, v.z, cp, cdiff.b, f0.b, sigma));
}
#endif
