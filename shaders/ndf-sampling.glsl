// Microfacet normals for the lab's sampling (importance sampling, its reference, the split sum's prefilter),
// drawn from the chosen NDF (NDF_GGX or NDF_BECKMANN: the two with a sampling routine), and the density
// D(m)(n·m) they are drawn with.
#include "ndf-term.glsl"
#include "integrate.glsl"

vec3 sampleLobeNormal(vec2 u, float alpha) {
#if defined(NDF_BECKMANN)
  return sampleBeckmannNormal(u, alpha);
#elif defined(NDF_GGX)
  return sampleGGXNormal(u, alpha);
#else
#error "ndf-sampling.glsl: only NDF_GGX and NDF_BECKMANN are sampled"
#endif
}

float lobeNormalPdf(vec3 m, float alpha) { return ndfTerm(m.z, dot(m.xy, m.xy), alpha) * m.z; }

// Density per steradian of l = reflect(v, m) for m drawn by sampleLobeNormal: D(m)(n·m) / (4 v·m).
float reflectedPdf(vec3 m, float vm, float alpha) { return vm > 0.0 ? lobeNormalPdf(m, alpha) / (4.0 * vm) : 0.0; }
