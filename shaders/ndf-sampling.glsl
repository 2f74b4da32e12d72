// Microfacet normals for the lab's sampling (importance sampling, its reference, the split sum's prefilter) and
// the density D_s(m)(n·m) they are drawn with. Callers weight each sample by the chosen NDF (ndfTerm, brdf.glsl)
// over that density, so the estimate is of the chosen lobe whichever distribution drew the normals.
#include "brdf.glsl"
#include "integrate.glsl"

vec3 sampleLobeNormal(vec2 u, float alpha) { return sampleGGXNormal(u, alpha); }

float lobeNormalPdf(vec3 m, float alpha) { return ndfGGXFromSin2(m.z, dot(m.xy, m.xy), alpha) * m.z; }

// Density per steradian of l = reflect(v, m) for m drawn by sampleLobeNormal: D_s(m)(n·m) / (4 v·m).
float reflectedPdf(vec3 m, float vm, float alpha) { return vm > 0.0 ? lobeNormalPdf(m, alpha) / (4.0 * vm) : 0.0; }
