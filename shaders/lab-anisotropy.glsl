// The material lab's specular lobe in its frame. With ANISOTROPIC (src/lab/lab-anisotropy.js decides it): the D
// ANISOTROPIC_D, the call of the chosen D's anisotropic form in the catalogue (or of the user's customDAniso, its
// chunk included under CUSTOM_DANISO) over the microfacet input at the pair uAlphaPair = (αx, αy) along the tangent
// field's t and b (lab-tangent.glsl), the V ANISOTROPIC_V likewise when the chosen V has such a form (or is the
// user's, CUSTOM_VANISO; any other V keeps its isotropic form at α), and with BENT_REFLECTION the reflected direction the approximations read the light in bent as Filament's
// and three.js's IBL bend it (else the mirror direction, to compare). Without ANISOTROPIC every function here is
// the isotropic lab's own (microfacetBRDF at α, the frame around n, the mirror direction). TANGENT_FIELD alone
// (OpenPBR Surface, a whole BRDF with its own anisotropy) takes only the tangent field's frame.
#ifdef ANISOTROPIC
#include "anisotropic.glsl"
#include "lab-tangent.glsl"
#ifdef CUSTOM_DANISO
#include "custom-DAniso.glsl"
#endif
#ifdef CUSTOM_VANISO
#include "custom-VAniso.glsl"
#endif
#elif defined(TANGENT_FIELD)
#include "lab-tangent.glsl"
#else
#include "env.glsl"
#endif

uniform vec2 uAlphaPair; // the microfacet input's (αx, αy), as every host feeds it
uniform float uAnisotropy;

vec2 alphaPair() { return uAlphaPair; }

// The frame the sphere is shaded in at n (columns t, b, n: local to view space).
mat3 shadingFrame(vec3 n) {
#if defined(ANISOTROPIC) || defined(TANGENT_FIELD)
  return tangentFrame(n);
#else
  return frameAround(n);
#endif
}

#if defined(ANISOTROPIC) && !defined(MEASURED)
vec3 lobeBRDF(vec3 l, vec3 v, vec3 f0) {
  vec3 hs = l + v;
  float hl = length(hs);
  if (!(l.z > 0.0 && v.z > 0.0) || hl < 1e-6) return vec3(0.0);
  MicrofacetInput m = microfacetInput(l, v, hs / hl, alphaPair());
#ifdef ANISOTROPIC_V
  float vis = ANISOTROPIC_V;
#else
  float vis = visibilityTerm(microfacetInput(l, v, m.h, vec2(uAlpha)));
#endif
  return fresnelTerm(f0, m.lh) * (ANISOTROPIC_D * vis / 4.0);
}
#else
#ifndef MEASURED
vec3 lobeBRDF(vec3 l, vec3 v, vec3 f0) { return microfacetBRDF(l, v, uAlpha, f0); }
#endif
#endif

// The bent reflection vector (Filament's IBL, in three.js's weighting): Filament's "anisotropic normal", v with its
// part along the grain removed (the grain: the axis of the smaller α, the brushing lines), mixed into n with weight
// 1 - (1 - a (1 - √α))⁴, and v mirrored about the result. A lookup direction, not a lobe: the stretched highlight
// of a prefiltered map or a sphere light is drawn by moving one direction, which is what the error image measures.
// (BENT_REFLECTION comes with ANISOTROPIC only: src/lab/lab-defines.js)
#ifdef BENT_REFLECTION
vec3 lobeReflection(vec3 v) { // anisotropic.glsl's: its a >= 0 takes b as the grain, as αx >= αy does here
  return anisotropicBentReflection(v, uAlpha, uAlphaPair.x >= uAlphaPair.y ? uAnisotropy : -uAnisotropy);
}
#else
vec3 lobeReflection(vec3 v) { return reflect(-v, vec3(0.0, 0.0, 1.0)); } // the mirror direction
#endif
