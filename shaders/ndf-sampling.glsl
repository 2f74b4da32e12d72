// Microfacet normals for the lab's sampling (importance sampling, its reference, the split sum's prefilter),
// drawn from the chosen NDF (sampleLobeNormal, generated: the NDFs whose catalogue entry names a sampler), and the
// density D(m)(n·m) they are drawn with.
#include "ndf-term.glsl"
#include "integrate.glsl"
#include "ndf-sampler.glsl"

float lobeNormalPdf(vec3 m, float alpha) { return ndfTerm(microfacetNormalInput(m, vec2(alpha))) * m.z; }

// Density per steradian of l = reflect(v, m) for m drawn by sampleLobeNormal: D(m)(n·m) / (4 v·m).
float reflectedPdf(vec3 m, float vm, float alpha) { return vm > 0.0 ? lobeNormalPdf(m, alpha) / (4.0 * vm) : 0.0; }
