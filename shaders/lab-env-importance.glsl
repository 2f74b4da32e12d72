// The environment by importance sampling, as a renderer would do it: uSamples directions per pixel, the same
// pattern on every pixel (hammersley), every term evaluated at each. A model's lobe and its diffuse term are
// sampled apart; a measured table (MEASURED), which has no diffuse part to sample alone, by both at once.
#include "lab-surround.glsl"
#include "lab-lobe-sampling.glsl"

#ifdef MEASURED
// A table's f under the map: one direction from the fitted lobe and one by cosine per sample, each weighted by
// the balance heuristic f (n·l) L / (pdf_lobe + pdf_cosine).
vec3 balancedSample(vec3 l, vec3 v, mat3 toWorld) {
  if (l.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float pdf = lobeReflectedPdf(v, h) + l.z / PI;
  return specularBRDF(l, v) * l.z * envMap(toWorld * l, 0.0) / max(pdf, 1e-30);
}

vec3 evaluateEnvironment(vec3 n, mat3 toWorld, vec3 v) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < uSamples; i++) {
    vec2 u = hammersley(i, uSamples);
    vec3 m = lobeNormal(v, u);
    sum += balancedSample(2.0 * dot(v, m) * m - v, v, toWorld) + balancedSample(sampleCosine(u), v, toWorld);
  }
  return sum / float(uSamples);
}
#else
// l = reflect(v, m) with m from the lobe (ndf-sampling.glsl), the diffuse by cosine sampling (pdf (n·l)/pi).
vec3 evaluateEnvironment(vec3 n, mat3 toWorld, vec3 v) {
  vec3 sum = vec3(0.0);
  int count = uSamples;
  for (int i = 0; i < count; i++) {
    vec2 u = hammersley(i, count);
    vec3 m = lobeNormal(v, u);
    float vm = dot(v, m);
    vec3 l = 2.0 * vm * m - v;
    if (vm > 0.0 && l.z > 0.0) {
      sum += specularBRDF(l, v) * l.z / max(lobeReflectedPdf(v, m), 1e-30) * envMap(toWorld * l, 0.0);
    }
    vec3 ld = sampleCosine(u);
    sum += diffuseBRDF(ld, v) * PI * envMap(toWorld * ld, 0.0);
  }
  return sum / float(count);
}
#endif
