// The diffuse term of brdf-sphere.frag.glsl, in the local frame (n = z): DIFFUSE_MODEL_* picks one of
// diffuse.glsl, Lambert without one. Reads uF0 (the trade-off models) and uSigma (Oren-Nayar, radians).
#include "diffuse.glsl"
uniform float uDiffuse;
uniform float uSigma;

// cos of the azimuth between l and v about n = z; 1 where either lies along n (the models do not depend on it there)
float cosPhiDiff(vec3 l, vec3 v) {
  float d = dot(l.xy, l.xy) * dot(v.xy, v.xy);
  return d > 1e-12 ? dot(l.xy, v.xy) / sqrt(d) : 1.0;
}

float diffuseTerm(vec3 l, vec3 v) {
#if defined(DIFFUSE_MODEL_FRESNEL_WEIGHTED)
  return diffuseFresnelWeighted(l.z, v.z, uF0, uDiffuse);
#elif defined(DIFFUSE_MODEL_ASHIKHMIN_SHIRLEY)
  return diffuseAshikhminShirley(l.z, v.z, uF0, uDiffuse);
#elif defined(DIFFUSE_MODEL_OREN_NAYAR)
  return diffuseOrenNayar(l.z, v.z, cosPhiDiff(l, v), uSigma, uDiffuse);
#elif defined(DIFFUSE_MODEL_OREN_NAYAR_QUALITATIVE)
  return diffuseOrenNayarQualitative(l.z, v.z, cosPhiDiff(l, v), uSigma, uDiffuse);
#else
  return l.z > 0.0 && v.z > 0.0 ? diffuseLambert(uDiffuse) : 0.0; // 0 below the horizon, as every other model
#endif
}
