// A sphere shaded by one BRDF under one punctual light (the talk's L = pi f c_light (n·l)), or, with FURNACE, in a
// uniform white environment with F = 1: the directional albedo E(n·v), scale + bias of the split-sum table uDfg
// (GGX, height-correlated Smith); with COMPENSATION_KULLA_CONTY or COMPENSATION_TURQUIN, that albedo with the
// energy compensation (multiple-scattering.glsl).
// Under the light the BRDF has two layers: the specular lobe of brdf.glsl (its term switches NDF_*, VIS_*, F_*
// pick D, V and F), off with SPECULAR_OFF; and the diffuse term of diffuse-term.glsl, there when a DIFFUSE_* term
// switch is given and not DIFFUSE_OFF. Only what is on compiles.
// Roughness is the microfacet input's pair uAlphaPair = (αx, αy), along the tangent and the bitangent; the tangent
// runs along the view-space axis uTangent, projected on each point's tangent plane (a field that does not swirl,
// unlike cross(z, n)): an anisotropic highlight stretches along it. The furnace's tables are isotropic: they read αx.
// With SPHERE_IMPOSTOR the sphere is ray-traced on a quad (sphere-impostor.glsl: the sphere grid); without, it is a
// mesh with interpolated normals (surface.vert.glsl: bench/versus-three.js).
#include "color.glsl"
#if defined(COMPENSATION_KULLA_CONTY) || defined(COMPENSATION_TURQUIN)
#include "multiple-scattering.glsl"
#elif defined(FURNACE)
#include "integrate.glsl"
#else
#ifndef SPECULAR_OFF
#include "brdf.glsl"
#endif
#include "diffuse-term.glsl"
#if !defined(DIFFUSE_TERM_NONE) && !defined(DIFFUSE_OFF)
#define DIFFUSE_LAYER
#endif
#endif

#ifdef SPHERE_IMPOSTOR
#include "sphere-impostor.glsl"
#else
in vec3 vNormal;
in vec3 vViewPosition;
#endif
uniform vec3 uLightDir;
uniform float uLightIntensity;
uniform float uExposure;
uniform vec2 uAlphaPair;
uniform vec3 uTangent;
uniform float uF0;
#if defined(FURNACE) && !defined(COMPENSATION_KULLA_CONTY) && !defined(COMPENSATION_TURQUIN)
uniform sampler2D uDfg;
#endif
#ifdef DIFFUSE_LAYER
uniform float uDiffuse;
uniform float uSigma;
#endif
out vec4 fragColor;

void main() {
#ifdef SPHERE_IMPOSTOR
  SpherePixel pixel = spherePixel();
  vec3 n = pixel.n;
  vec3 v = vec3(0.0, 0.0, 1.0);
#else
  vec3 n = normalize(vNormal);
  vec3 v = isOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
#endif
  float nv = dot(n, v);
#if defined(COMPENSATION_KULLA_CONTY)
  float radiance = specularAlbedoKullaConty(nv, uAlphaPair.x, 1.0);
#elif defined(COMPENSATION_TURQUIN)
  float radiance = specularAlbedoTurquin(nv, uAlphaPair.x, 1.0);
#elif defined(FURNACE)
  vec2 ab = texture(uDfg, dfgTableUv(nv, uAlphaPair.x)).rg;
  float radiance = ab.x + ab.y;
#else
  // the BRDF works in a frame where n = z: t is uTangent in the tangent plane (where n is along uTangent, the
  // sphere's outline, or uTangent is 0, the old frame around the view axis)
  vec3 tp = uTangent - n * dot(n, uTangent);
  vec3 t = dot(tp, tp) > 1e-8 ? normalize(tp)
    : normalize(abs(n.z) < 0.999 ? cross(vec3(0.0, 0.0, 1.0), n) : cross(vec3(1.0, 0.0, 0.0), n));
  mat3 toLocal = transpose(mat3(t, cross(n, t), n));
  vec3 l = toLocal * normalize(uLightDir);
  vec3 vLocal = toLocal * v;
  float f = 0.0;
#ifndef SPECULAR_OFF
  f += microfacetBRDF(l, vLocal, uAlphaPair, vec3(uF0)).x;
#endif
#ifdef DIFFUSE_LAYER
  f += diffuseTerm(l, vLocal, vec3(uDiffuse), vec3(uF0), uSigma).x;
#endif
  float radiance = PI * f * uLightIntensity * max(l.z, 0.0);
#endif
#ifdef SPHERE_IMPOSTOR
  fragColor = overBackground(vec3(radiance * uExposure), pixel.coverage);
#else
  fragColor = vec4(linearToSrgb(vec3(radiance * uExposure)), 1.0);
#endif
}
