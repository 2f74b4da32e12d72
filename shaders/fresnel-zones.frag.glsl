// The Fresnel-zones demo. Switches (one program per combination, only the used code is compiled):
//   SHOW_FRESNEL   draw the material's Fresnel reflectance of n·v instead of zone colours, the zones' borders
//                  drawn over it as lines (so the legend's shares have their picture)
//   ZONE_BY_LH     zones of l·h instead of n·v
//   WEIGHTED       weight each zone by the rest of the specular BRDF, D·V, with the terms' own switches
//                  NDF_* and VIS_* (the catalogue's; the widget passes GGX and height-correlated Smith)
//   METAL / FRESNEL_SCHLICK   which Fresnel the material uses
//   STATS_PASS     write one-hot zone coverage (times the weight) for the GPU sum instead of a colour
#include "zones.glsl"
#include "color.glsl"
#ifdef SHOW_FRESNEL
#include "fresnel.glsl"
#endif
#ifdef WEIGHTED
#include "ndf-term.glsl"
#include "visibility-term.glsl"
#endif

in vec3 vNormal;
in vec3 vViewPosition;
uniform vec3 uLightDir;
uniform vec3 uEta;
uniform vec3 uK;
uniform vec3 uF0;
uniform vec2 uAlphaPair; // (αx, αy), equal here: the zones are isotropic
uniform float uExposure;
uniform vec3 uZoneColors[3];
out vec4 fragColor;

#ifdef SHOW_FRESNEL
vec3 materialFresnel(float c) {
#if defined(FRESNEL_SCHLICK)
  return fresnelSchlick(uF0, c);
#elif defined(METAL)
  return fresnelConductor(c, uEta, uK);
#else
  return vec3(fresnelDielectric(c, uEta.r));
#endif
}
#endif

void main() {
  vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
  vec3 v = isOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
  float nv = saturate(dot(n, v));
#ifdef ZONE_BY_LH
  vec3 l = normalize(uLightDir);
  vec3 hs = l + v;
  float hl = length(hs);
  vec3 h = hl > 1e-6 ? hs / hl : n;
  int zone = int(fresnelZone(dot(l, h)));
#else
  int zone = int(fresnelZone(nv));
#endif
  float weight = 1.0;
#ifdef WEIGHTED
  float nl = dot(n, l);
  float nh = dot(n, h);
  // sin²θh from n·h as ndfGGX has it (no local frame)
  MicrofacetInput mi = microfacetInputFromCosines(nl, nv, nh, dot(l, h), sin2FromCos(min(nh, 1.0)), uAlphaPair);
  weight = PI * ndfTerm(mi) * visibilityTerm(mi) / 4.0 * max(nl, 0.0);
#endif
#ifdef STATS_PASS
  fragColor = vec4(zone == 0 ? weight : 0.0, zone == 1 ? weight : 0.0, zone == 2 ? weight : 0.0, 1.0);
#else
#if defined(SHOW_FRESNEL)
  vec3 linear = materialFresnel(nv);
  // a border pixel: a step of 1.5 pixels towards the centre is in the next zone; drawn in the outer zone's colour
  if (int(fresnelZone(nv + 1.5 * fwidth(nv))) != zone) linear = uZoneColors[zone];
#elif defined(WEIGHTED)
  vec3 linear = uZoneColors[zone] * (1.0 - exp(-uExposure * weight));
#else
  vec3 linear = uZoneColors[zone];
#endif
  fragColor = vec4(linearToSrgb(linear), 1.0);
#endif
}
