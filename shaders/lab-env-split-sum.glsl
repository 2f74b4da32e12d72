// The environment by the split sum (Karis 2013): the map prefiltered with the chosen NDF's lobe (n = v = r) times
// the DFG albedo, Kulla & Conty's share on the irradiance; the diffuse by irradiance × Lambert.
#include "lab-env-irradiance.glsl"
#include "lab-albedo.glsl"

uniform sampler2DArray uPrefiltered;
uniform float uPrefilterLevels;

// The map prefiltered with the chosen NDF's lobe: layers at perceptual roughness k/levels, level 0 the map itself.
vec3 prefiltered(vec3 r, float alpha) {
  float level = sqrt(alpha) * uPrefilterLevels;
  float k = min(floor(level), uPrefilterLevels - 1.0);
  float t = level - k;
  vec2 uv = equirectUv(r);
  vec3 lo = k < 0.5 ? textureLod(uEnv, uv, 0.0).rgb : texture(uPrefiltered, vec3(uv, k - 1.0)).rgb;
  vec3 hi = texture(uPrefiltered, vec3(uv, k)).rgb;
  return uEnvIntensity * mix(lo, hi, t);
}

vec3 evaluateEnvironment(vec3 n, mat3 toWorld, vec3 v) {
#ifdef ANISOTROPIC
  vec3 rWorld = toWorld * lobeReflection(v); // the bent reflection vector: the prefilter has no anisotropic form
#else
  vec3 rWorld = reflect(-vec3(0.0, 0.0, 1.0), n);
#endif
  vec3 specular = prefiltered(rWorld, uAlpha) * dfgAlbedo(v.z);
  vec3 irradiance = envIrradiance(n);
  specular += multipleAlbedo(v.z) * irradiance;
  return specularOn * specular + diffuseColor * irradiance;
}
