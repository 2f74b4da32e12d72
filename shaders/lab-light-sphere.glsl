// The material lab's sphere light as a punctual light at its centre (AREA_CENTRE), or by the representative point
// (Karis 2013): the specular from the point of the disc nearest the reflected ray, the diffuse from the centre.
#include "lab-light-sphere-pars.glsl"
#include "lighting.glsl"

vec3 evaluateSphereLight(mat3 toLocal, vec3 v) {
  vec3 d = toLocal * uSphereDir;
  vec3 cLight = sphereLightCLight(1.0, uSphereSin) * uSphereRadiance;
#ifdef AREA_CENTRE
  return punctualRadiance(d, v, cLight);
#else
  vec3 lRep = sphereLightRepresentativeDir(lobeReflection(v), d, uSphereSin);
  vec3 specular = PI * specularBRDF(lRep, v) * cLight * max(lRep.z, 0.0) * sphereLightNormalization(uAlpha, uSphereSin);
  return specular + PI * diffuseBRDF(d, v) * cLight * max(d.z, 0.0);
#endif
}
