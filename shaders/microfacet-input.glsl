// The one input every D and V term reads (the dispatch ndfTerm, visibilityTerm takes it), the GLSL twin of
// src/math/catalogue/microfacet-input.js: l, v, h in the tangent frame (t, b, n) = (x, y, z), the cosines, sin²θh
// from the half vector itself (precise near n, where 1 - (n·h)² cancels) and the roughness pair (αx, αy),
// isotropic when equal. A catalogue term's args name these fields.
#include "common.glsl"

struct MicrofacetInput {
  vec3 l;
  vec3 v;
  vec3 h;
  float nl;
  float nv;
  float nh;
  float lh;
  float sin2h;
  vec2 alpha;
};

// unit l, v and their unit half vector h
MicrofacetInput microfacetInput(vec3 l, vec3 v, vec3 h, vec2 alpha) {
  return MicrofacetInput(l, v, h, l.z, v.z, h.z, dot(l, h), dot(h.xy, h.xy), alpha);
}

// A microfacet normal alone (a sampler's density D(m)(n·m)): l = v = m.
MicrofacetInput microfacetNormalInput(vec3 m, vec2 alpha) { return microfacetInput(m, m, m, alpha); }

// From the cosines alone, for a caller without a frame (a probe at one surface point): the vectors are put in
// the plane y = 0 from them, which serves an isotropic term (it reads the cosines only), not an anisotropic one.
MicrofacetInput microfacetInputFromCosines(float nl, float nv, float nh, float lh, float sin2h, vec2 alpha) {
  vec3 h = vec3(sqrt(max(sin2h, 0.0)), 0.0, nh);
  vec3 l = vec3(sqrt(sin2FromCos(clamp(nl, -1.0, 1.0))), 0.0, nl);
  vec3 v = vec3(-sqrt(sin2FromCos(clamp(nv, -1.0, 1.0))), 0.0, nv);
  return MicrofacetInput(l, v, h, nl, nv, nh, lh, sin2h, alpha);
}
