// The microfacet BRDF F·D·V/4 for unit vectors l, v in the local frame (n = z), mirrors microfacetBRDF of
// src/math/brdf.js. The terms are chosen by their defines, one of each family: F_* (fresnelTerm), NDF_* (ndfTerm),
// VIS_* (visibilityTerm), as the catalogue names them (src/math/catalogue; termDefines gives them). The three
// dispatch chunks are generated from the catalogue (src/core/gpu/term-chunks.js): each is an explicit chain of its
// terms that declares the uniforms of the chosen term only (uExponent, uA1, uA2, uSgdP, uSgdNorm) and stops with #error
// when no term of its family is chosen. 0 at or below the horizon, and for l = -v (no half vector).
#include "fresnel-term.glsl"
#include "ndf-term.glsl"
#include "visibility-term.glsl"

// RGB F0 (a metal's colour): D and V once, F per channel.
vec3 microfacetBRDF(vec3 l, vec3 v, float alpha, vec3 f0) {
  float nl = l.z;
  float nv = v.z;
  vec3 hs = l + v;
  float hl = length(hs);
  if (!(nl > 0.0 && nv > 0.0) || hl < 1e-6) return vec3(0.0);
  vec3 h = hs / hl;
  float lh = dot(l, h);
  return fresnelTerm(f0, lh) * (ndfTerm(h.z, dot(h.xy, h.xy), alpha) * visibilityTerm(nl, nv, h.z, lh, alpha) / 4.0);
}

float microfacetBRDF(vec3 l, vec3 v, float alpha, float f0) { return microfacetBRDF(l, v, alpha, vec3(f0)).x; }
