// A sphere shaded by one microfacet BRDF under one punctual light (the talk's L = pi f c_light (n·l)),
// (with DIFFUSE_LAMBERT plus a Lambert term), or, with FURNACE, in a uniform white environment with F = 1: the
// directional albedo E(n·v), scale + bias of the split-sum table uDfg (GGX, height-correlated Smith).
// The term switches of brdf.glsl pick D (NDF_*), V (VIS_*) and F (F_ONE or Schlick); only those compile.
// With DIFFUSE_ONLY the sphere has a diffuse term alone, picked by DIFFUSE_MODEL_* (Lambert without one).
#include "color.glsl"
#ifdef FURNACE
#include "integrate.glsl"
#elif !defined(DIFFUSE_ONLY)
#include "brdf.glsl"
#endif

in vec3 vNormal;
in vec3 vViewPosition;
uniform vec3 uLightDir;
uniform float uLightIntensity;
uniform float uExposure;
uniform float uAlpha;
uniform float uF0;
#ifdef FURNACE
uniform sampler2D uDfg;
#endif
out vec4 fragColor;

// either switch brings the diffuse term in (included once)
#ifdef DIFFUSE_LAMBERT
#include "diffuse-sphere.glsl"
#endif
#ifdef DIFFUSE_ONLY
#include "diffuse-sphere.glsl"
#endif

void main() {
  vec3 n = normalize(vNormal);
  vec3 v = isOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vViewPosition);
  float nv = dot(n, v);
#ifdef FURNACE
  vec2 ab = texture(uDfg, dfgTableUv(nv, uAlpha)).rg;
  float radiance = ab.x + ab.y;
#else
  // the BRDF works in a frame where n = z: build one around the shading normal
  vec3 t = normalize(abs(n.z) < 0.999 ? cross(vec3(0.0, 0.0, 1.0), n) : cross(vec3(1.0, 0.0, 0.0), n));
  mat3 toLocal = transpose(mat3(t, cross(n, t), n));
  vec3 l = toLocal * normalize(uLightDir);
#ifdef DIFFUSE_ONLY
  float f = diffuseTerm(l, toLocal * v);
#else
  float f = microfacetBRDF(l, toLocal * v, uAlpha, uF0);
#ifdef DIFFUSE_LAMBERT
  f += diffuseTerm(l, toLocal * v);
#endif
#endif
  float radiance = PI * f * uLightIntensity * max(l.z, 0.0);
#endif
  fragColor = vec4(linearToSrgb(vec3(radiance * uExposure)), 1.0);
}
