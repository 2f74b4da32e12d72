// Ambient light, uniform radiance from every direction: the specular albedo from the DFG table (lab-albedo.glsl),
// the diffuse albedo c of Lambert (the form it has, whatever diffuse term is chosen).
#include "lab-surround.glsl"
#include "lab-albedo.glsl"

vec3 evaluateAmbient(vec3 v) { return uAmbient * (specularOn * (dfgAlbedo(v.z) + multipleAlbedo(v.z)) + diffuseColor); }
