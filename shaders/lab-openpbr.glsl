// The material lab's BRDF when it is OpenPBR Surface (shaders/openpbr.glsl): lab-material.glsl's path for a BRDF
// that is whole (MEASURED, with OPENPBR) reads it through measuredBRDF(n, l, v), n = (0, 0, 1) there, in the local
// frame of the sphere's point. The material is the uniform uOpenPbr (src/lab/lab-uniforms.js fills it from the
// panel, clamped as openPbrMaterial clamps it in JS), the albedo table uOpenPbrAlbedo.
#include "openpbr.glsl"

uniform OpenPbrMaterial uOpenPbr;

vec3 measuredBRDF(vec3 n, vec3 l, vec3 v) { return openPbrBRDF(l, v, openPbrClamp(uOpenPbr)); }
