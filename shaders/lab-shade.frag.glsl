// The material lab: one orthographic unit sphere seen along -z (v = z), shaded by the chosen BRDF
// (lab-material.glsl) under the lights that are on, each by its chunk: LIGHT_PUNCTUAL (exact), LIGHT_SPHERE (at its
// centre with AREA_CENTRE, else by the representative point), LIGHT_ENV by ENV_MIRROR, ENV_SPLIT_SUM or
// ENV_IMPORTANCE (none: the map only shows behind the sphere), LIGHT_AMBIENT; or with REFERENCE all of them by Monte
// Carlo batches whose running mean converges to the reflectance equation (lab-reference.glsl). Alpha is the sphere
// mask (1 on it, 0 off it). The approximations follow the chosen F, D and V: uDfg is the DFG table and uPrefiltered
// the map prefiltered for them; where a method has no form for the chosen diffuse term, irradiance × Lambert stands
// in (src/lab/lab-approximations.js says so on the page).
uniform vec2 uSize;
uniform float uExtent;
uniform int uSamples; // per pixel: of importance sampling, or of each light in one reference batch

#include "lab-material.glsl"
#include "lab-surround.glsl"
#ifdef LIGHT_PUNCTUAL
#include "lab-light-punctual.glsl"
#endif
#ifdef REFERENCE
#include "lab-reference.glsl"
#else
#ifdef LIGHT_SPHERE
#include "lab-light-sphere.glsl"
#endif
#if defined(ENV_MIRROR)
#include "lab-env-mirror.glsl"
#elif defined(ENV_SPLIT_SUM)
#include "lab-env-split-sum.glsl"
#elif defined(ENV_IMPORTANCE)
#include "lab-env-importance.glsl"
#endif
#ifdef LIGHT_AMBIENT
#include "lab-light-ambient.glsl"
#endif
#endif

out vec4 fragColor;

// Each light on, by its method (or by Monte Carlo with REFERENCE), summed.
void main() {
  vec2 p = (2.0 * gl_FragCoord.xy / uSize - 1.0) * uExtent;
  float r2 = dot(p, p);
  if (r2 >= 1.0) {
    fragColor = vec4(surroundRadiance(normalize(vec3(0.5 * p, -1.0))), 0.0);
    return;
  }
  vec3 n = vec3(p, sqrt(1.0 - r2));
  mat3 toWorld = shadingFrame(n);
  mat3 toLocal = transpose(toWorld);
  vec3 v = toLocal * vec3(0.0, 0.0, 1.0);
#ifdef REFERENCE
  vec2 shift = referenceShift();
#endif
  vec3 Lo = vec3(0.0);
#ifdef LIGHT_PUNCTUAL
  Lo += evaluatePunctual(toLocal, v);
#endif
#if defined(LIGHT_SPHERE) && defined(REFERENCE)
  Lo += evaluateReferenceSphereLight(toLocal, v, shift);
#elif defined(LIGHT_SPHERE)
  Lo += evaluateSphereLight(toLocal, v);
#endif
#if defined(ENV_MIRROR) || defined(ENV_SPLIT_SUM) || defined(ENV_IMPORTANCE)
  Lo += evaluateEnvironment(n, toWorld, v);
#endif
#if defined(LIGHT_ENV) && defined(REFERENCE) || defined(LIGHT_AMBIENT) && defined(REFERENCE)
  Lo += evaluateReferenceSurround(toWorld, toLocal, v, shift);
#elif defined(LIGHT_AMBIENT)
  Lo += evaluateAmbient(v);
#endif
#ifdef REFERENCE
  Lo = runningMean(Lo);
#endif
  fragColor = vec4(Lo, 1.0);
}
