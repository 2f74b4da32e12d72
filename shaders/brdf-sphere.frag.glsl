// A sphere shaded by one microfacet BRDF under one punctual light (the talk's L = pi f c_light (n·l)),
// or, with FURNACE, in a uniform white environment with F = 1 (the directional albedo E(n·v)).
// The term switches pick D (NDF_*), V (VIS_*) and F (F_ONE or Schlick); only the chosen ones compile.
#include "color.glsl"
#ifdef FURNACE
#include "integrate.glsl"
#else
#include "visibility.glsl"
#include "fresnel.glsl"
#endif

in vec3 vNormal;
in vec3 vViewPosition;
uniform vec3 uLightDir;
uniform float uLightIntensity;
uniform float uExposure;
uniform float uAlpha;
uniform float uExponent;
uniform float uA1;
uniform float uA2;
uniform float uSgdP;
uniform float uF0;
out vec4 fragColor;

#ifndef FURNACE
float ndfTerm(float nh) {
#if defined(NDF_BECKMANN)
  return ndfBeckmann(nh, uAlpha);
#elif defined(NDF_BLINN_PHONG)
  return ndfBlinnPhong(nh, uExponent);
#elif defined(NDF_ABC)
  return ndfABC(nh, uA1, uA2);
#elif defined(NDF_SGD)
  return ndfSGD(nh, uAlpha, uSgdP);
#else
  return ndfGGX(nh, uAlpha);
#endif
}

float visibilityTerm(float nl, float nv, float nh, float lh) {
#if defined(VIS_IMPLICIT)
  return visibilityImplicit(nl, nv);
#elif defined(VIS_COOK_TORRANCE)
  return visibilityCookTorrance(nl, nv, nh, lh);
#elif defined(VIS_KELEMEN)
  return aboveHorizon(nl, nv) ? visibilityKelemen(lh) : 0.0;
#elif defined(VIS_SMITH_GGX_SEPARABLE)
  return visibilitySmithGGXSeparable(nl, nv, uAlpha);
#elif defined(VIS_SMITH_GGX_FAST)
  return visibilitySmithGGXCorrelatedFast(nl, nv, uAlpha);
#elif defined(VIS_SCHLICK_GGX)
  return visibilitySchlickGGX(nl, nv, uAlpha);
#elif defined(VIS_SMITH_BECKMANN)
  return visibilitySmithBeckmannSeparable(nl, nv, uAlpha);
#else
  return visibilitySmithGGXCorrelated(nl, nv, uAlpha);
#endif
}
#endif

void main() {
  vec3 n = normalize(vNormal);
  vec3 v = isOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
  float nv = dot(n, v);
#ifdef FURNACE
  float radiance = albedoGGX(nv, uAlpha, FURNACE_SAMPLES);
#else
  vec3 l = normalize(uLightDir);
  vec3 hs = l + v;
  float hl = length(hs);
  float radiance = 0.0;
  if (hl > 1e-6) {
    vec3 h = hs / hl;
    float nl = dot(n, l);
    float nh = dot(n, h);
    float lh = dot(l, h);
#ifdef F_ONE
    float F = 1.0;
#else
    float F = fresnelSchlick(uF0, lh);
#endif
    float f = F * ndfTerm(nh) * visibilityTerm(nl, nv, nh, lh) / 4.0;
    radiance = PI * f * uLightIntensity * max(nl, 0.0);
  }
#endif
  fragColor = vec4(linearToSrgb(vec3(radiance * uExposure)), 1.0);
}
