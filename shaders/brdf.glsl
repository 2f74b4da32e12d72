// The microfacet BRDF F·D·V/4 for unit vectors l, v in the local frame (n = z), mirrors microfacetBRDF of
// src/math/brdf.js. The terms are chosen by switches (NDF_*, VIS_*, F_ONE); without any it is GGX,
// height-correlated Smith and Schlick. 0 at or below the horizon, and for l = -v (no half vector).
#include "visibility.glsl"
#include "fresnel.glsl"

uniform float uExponent;
uniform float uA1;
uniform float uA2;
uniform float uSgdP;

// sin2 of the half vector's angle, taken from h.xy: exact where 1 - nh² is not (see ndfGGXFromSin2)
float ndfTerm(float nh, float sin2h, float alpha) {
#if defined(NDF_BECKMANN)
  return ndfBeckmannFromSin2(nh, sin2h, alpha);
#elif defined(NDF_BLINN_PHONG)
  return ndfBlinnPhongFromSin2(nh, sin2h, uExponent);
#elif defined(NDF_ABC)
  return ndfABC(nh, uA1, uA2);
#elif defined(NDF_SGD)
  return ndfSGD(nh, alpha, uSgdP);
#else
  return ndfGGXFromSin2(nh, sin2h, alpha);
#endif
}

float visibilityTerm(float nl, float nv, float nh, float lh, float alpha) {
#if defined(VIS_IMPLICIT)
  return visibilityImplicit(nl, nv);
#elif defined(VIS_COOK_TORRANCE)
  return visibilityCookTorrance(nl, nv, nh, lh);
#elif defined(VIS_KELEMEN)
  return aboveHorizon(nl, nv) ? visibilityKelemen(lh) : 0.0;
#elif defined(VIS_SMITH_GGX_SEPARABLE)
  return visibilitySmithGGXSeparable(nl, nv, alpha);
#elif defined(VIS_SMITH_GGX_FAST)
  return visibilitySmithGGXCorrelatedFast(nl, nv, alpha);
#elif defined(VIS_SCHLICK_GGX)
  return visibilitySchlickGGX(nl, nv, alpha);
#elif defined(VIS_SMITH_BECKMANN)
  return visibilitySmithBeckmannSeparable(nl, nv, alpha);
#else
  return visibilitySmithGGXCorrelated(nl, nv, alpha);
#endif
}

// RGB F0 (a metal's colour): D and V once, F per channel.
vec3 microfacetBRDF(vec3 l, vec3 v, float alpha, vec3 f0) {
  float nl = l.z;
  float nv = v.z;
  vec3 hs = l + v;
  float hl = length(hs);
  if (!(nl > 0.0 && nv > 0.0) || hl < 1e-6) return vec3(0.0);
  vec3 h = hs / hl;
  float lh = dot(l, h);
#ifdef F_ONE
  vec3 F = vec3(1.0);
#else
  vec3 F = fresnelSchlick(f0, lh);
#endif
  return F * (ndfTerm(h.z, dot(h.xy, h.xy), alpha) * visibilityTerm(nl, nv, h.z, lh, alpha) / 4.0);
}

float microfacetBRDF(vec3 l, vec3 v, float alpha, float f0) { return microfacetBRDF(l, v, alpha, vec3(f0)).x; }
