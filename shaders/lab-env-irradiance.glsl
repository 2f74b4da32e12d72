// The irradiance of the lab's environment (uIrradiance, summed in JS from the map): the diffuse form the mirror
// and split-sum methods have, irradiance × Lambert, whatever diffuse term is chosen.
#include "lab-surround.glsl"

uniform sampler2D uIrradiance;

// The radiance of a white Lambertian surface of normal n (world space) under the map.
vec3 envIrradiance(vec3 n) { return uEnvIntensity * texture(uIrradiance, equirectUv(n)).rgb; }
