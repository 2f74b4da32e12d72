// The lab's specular samples: microfacet normals drawn from the chosen NDF (ndf-sampling.glsl) and the density per
// steradian of l = reflect(v, m); with ANISOTROPIC, the visible normals of the anisotropic GGX lobe (Dupuy &
// Benyoub 2023), whose density G1(v) D(m) / (4 n·v) follows the stretched lobe, so the estimate converges.
#include "ndf-sampling.glsl"

vec3 lobeNormal(vec3 v, vec2 u) {
#ifdef ANISOTROPIC
  return sampleVisibleNormalGGXAniso(v, alphaPair(), u);
#else
  return sampleLobeNormal(u, uAlpha);
#endif
}

float lobeReflectedPdf(vec3 v, vec3 m) {
#ifdef ANISOTROPIC
  return reflectedPdfGGXAniso(v, m, alphaPair());
#else
  return reflectedPdf(m, dot(v, m), uAlpha);
#endif
}
