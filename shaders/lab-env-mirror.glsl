// The environment by the mirror direction alone: F at n·v (the half vector of a mirror being n) times the map in
// the reflected direction, the roughness ignored; the diffuse by irradiance × Lambert.
#include "lab-env-irradiance.glsl"

vec3 evaluateEnvironment(vec3 n, mat3 toWorld, vec3 v) {
  vec3 rWorld = reflect(-vec3(0.0, 0.0, 1.0), n);
#ifdef F_ONE
  vec3 specular = envMap(rWorld, 0.0);
#else
  vec3 specular = fresnelSchlick(uF0, v.z) * envMap(rWorld, 0.0);
#endif
  vec3 irradiance = envIrradiance(n);
  return specularOn * specular + diffuseColor * irradiance;
}
