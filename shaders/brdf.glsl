// The microfacet BRDF F·D·V/4 for unit vectors l, v in the local frame (n = z), mirrors microfacetBRDF of
// src/math/brdf.js. The terms are chosen by their defines, one of each family: F_* (fresnelTerm), NDF_* (ndfTerm),
// VIS_* (visibilityTerm), as the catalogue names them (src/math/catalogue; termDefines gives them). The three
// dispatch chunks are generated from the catalogue (src/core/gpu/term-chunks.js): each is an explicit chain of its
// terms that declares the uniforms of the chosen term only (each bound to its parameter: uExponent, uA1, uA2, uSgdP,
// uSgdNorm) and stops with #error when no term of its family is chosen. D and V read one microfacet input
// (microfacet-input.glsl): l, v, h in the tangent frame and the roughness pair (αx, αy). 0 at or below the
// horizon, and for l = -v (no half vector).
#include "fresnel-term.glsl"
#include "ndf-term.glsl"
#include "visibility-term.glsl"

// RGB F0 (a metal's colour): D and V once, F per channel. alpha = (αx, αy), along the tangent and bitangent.
vec3 microfacetBRDF(vec3 l, vec3 v, vec2 alpha, vec3 f0) {
  vec3 hs = l + v;
  float hl = length(hs);
  if (!(l.z > 0.0 && v.z > 0.0) || hl < 1e-6) return vec3(0.0);
  MicrofacetInput m = microfacetInput(l, v, hs / hl, alpha);
  return fresnelTerm(f0, m.lh) * (ndfTerm(m) * visibilityTerm(m) / 4.0);
}
vec3 microfacetBRDF(vec3 l, vec3 v, float alpha, vec3 f0) { return microfacetBRDF(l, v, vec2(alpha), f0); }

float microfacetBRDF(vec3 l, vec3 v, float alpha, float f0) { return microfacetBRDF(l, v, alpha, vec3(f0)).x; }
