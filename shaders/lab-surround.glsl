// The light all around the lab's sphere: the environment map (env.glsl's equirectangular layout) times its
// intensity, and the ambient radiance. What the background shows and what the reference integrates at once.
#include "env.glsl"

uniform sampler2D uEnv;
uniform float uEnvIntensity;
uniform vec3 uAmbient;

vec3 envMap(vec3 dWorld, float lod) { return uEnvIntensity * textureLod(uEnv, equirectUv(dWorld), lod).rgb; }

// The radiance from direction dWorld: the map and the ambient light, those that are on.
vec3 surroundRadiance(vec3 dWorld) {
  vec3 L = vec3(0.0);
#ifdef LIGHT_ENV
  L += envMap(dWorld, 0.0);
#endif
#ifdef LIGHT_AMBIENT
  L += uAmbient;
#endif
  return L;
}
