// OpenPBR Surface as one BRDF, mirrors src/math/openpbr.js (see there for the composition, the subset and the
// sources): vec3 openPbrBRDF(vec3 l, vec3 v, OpenPbrMaterial m), in 1/sr (no cosine), l and v unit vectors in the
// local frame (n = z, tangent = x). The fields of OpenPbrMaterial are the specification's parameter names;
// openPbrDefaults() gives its defaults (base_color 0.8, specular_roughness 0.3, specular_ior 1.5, coat_ior 1.6,
// fuzz_roughness 0.5, coat_darkening 1, every weight 1 but coat_weight, fuzz_weight and base_metalness 0, every
// other colour 1, every other roughness and anisotropy 0). The caller keeps values in the specification's ranges
// (openPbrClamp does what openPbrMaterial does in JS) and binds the albedo table uOpenPbrAlbedo
// (openPbrAlbedoTable() in src/math/openpbr-albedo.js, a 64 × 128 RGBA float texture).
#include "fresnel.glsl"
#include "anisotropic.glsl"
#include "openpbr-diffuse.glsl"
#include "openpbr-fuzz.glsl"
#include "openpbr-albedo.glsl"

struct OpenPbrMaterial {
  float base_weight;
  vec3 base_color;
  float base_metalness;
  float base_diffuse_roughness;
  float specular_weight;
  vec3 specular_color;
  float specular_roughness;
  float specular_roughness_anisotropy;
  float specular_ior;
  float coat_weight;
  vec3 coat_color;
  float coat_roughness;
  float coat_roughness_anisotropy;
  float coat_ior;
  float coat_darkening;
  float fuzz_weight;
  vec3 fuzz_color;
  float fuzz_roughness;
};

OpenPbrMaterial openPbrDefaults() {
  return OpenPbrMaterial(1.0, vec3(0.8), 0.0, 0.0, 1.0, vec3(1.0), 0.3, 0.0, 1.5, 0.0, vec3(1.0), 0.0, 0.0, 1.6, 1.0,
    0.0, vec3(1.0), 0.5);
}

// the specification's ranges: [0, 1], but specular_weight >= 0 and the indices >= 1 (see openPbrMaterial)
OpenPbrMaterial openPbrClamp(OpenPbrMaterial m) {
  return OpenPbrMaterial(saturate(m.base_weight), saturate(m.base_color), saturate(m.base_metalness),
    saturate(m.base_diffuse_roughness), max(m.specular_weight, 0.0), saturate(m.specular_color),
    saturate(m.specular_roughness), saturate(m.specular_roughness_anisotropy), max(m.specular_ior, 1.0),
    saturate(m.coat_weight), saturate(m.coat_color), saturate(m.coat_roughness),
    saturate(m.coat_roughness_anisotropy), max(m.coat_ior, 1.0), saturate(m.coat_darkening),
    saturate(m.fuzz_weight), saturate(m.fuzz_color), saturate(m.fuzz_roughness));
}

float openPbrUnmodulatedEta(OpenPbrMaterial m) {
  float coated = m.specular_ior / m.coat_ior;
  return mix(m.specular_ior, coated > 1.0 ? coated : 1.0 / coated, m.coat_weight);
}

float openPbrSpecularEta(OpenPbrMaterial m) {
  float eta = openPbrUnmodulatedEta(m);
  float f0 = (eta - 1.0) * (eta - 1.0) / ((eta + 1.0) * (eta + 1.0));
  float eps = sign(eta - 1.0) * sqrt(clamp(m.specular_weight * f0, 0.0, 0.99999));
  return (1.0 + eps) / (1.0 - eps);
}

float openPbrBaseRoughness(OpenPbrMaterial m) {
  float r2 = m.specular_roughness * m.specular_roughness;
  float c2 = m.coat_roughness * m.coat_roughness;
  return mix(m.specular_roughness, pow(min(1.0, r2 * r2 + 2.0 * c2 * c2), 0.25), m.coat_weight);
}

vec3 openPbrCoatDarkening(OpenPbrMaterial m, float nv) {
  float eta = m.coat_ior;
  float etaS = openPbrUnmodulatedEta(m);
  float fs = saturate(m.specular_weight * (etaS - 1.0) * (etaS - 1.0) / ((etaS + 1.0) * (etaS + 1.0)));
  float rb = mix(mix(1.0, m.specular_roughness, fs), m.specular_roughness, m.base_metalness);
  float k = mix(fresnelDielectric(nv, eta), 1.0 - (1.0 - fresnelDielectricAverage(eta)) / (eta * eta), rb);
  vec3 eb = mix(m.base_color, m.base_color * m.specular_weight, m.base_metalness);
  return mix(vec3(1.0), (1.0 - k) / (1.0 - eb * k), m.coat_weight * m.coat_darkening);
}

float openPbrGgxLobe(vec3 l, vec3 v, vec3 h, vec2 alphas) {
  return ndfGGXAniso(h, alphas) * visibilitySmithGGXCorrelatedAniso(l, v, alphas) / 4.0;
}

float refractedCos(float mu, float eta) { return sqrt(max(1.0 - (1.0 - mu * mu) / (eta * eta), 0.0)); }

// each layer's part, weighted so that they sum to openPbrBRDF: specular, diffuse (the dielectric base's gloss and
// diffuse lobe), metal, coat, fuzz. Compile-time switches take a layer out as its weight at 0 would, its work too
// (the bench times each layer's own cost, bench/openpbr-family.js; the lab compiles them all): OPENPBR_NO_SPECULAR
// (specular_weight: the base's microfacet lobe, gloss and metal), OPENPBR_NO_COAT, OPENPBR_NO_FUZZ.
void openPbrLayers(vec3 l, vec3 v, OpenPbrMaterial m, out vec3 specular, out vec3 diffuse, out vec3 metal,
                   out vec3 coat, out vec3 fuzz) {
  specular = diffuse = metal = coat = fuzz = vec3(0.0);
  if (!(l.z > 0.0 && v.z > 0.0)) return;
  vec3 h = normalize(l + v);
  float lh = dot(l, h);
  float nv = v.z;
#ifdef OPENPBR_NO_SPECULAR
  m.specular_weight = 0.0;
#endif
#ifdef OPENPBR_NO_COAT
  m.coat_weight = 0.0;
#endif
#ifdef OPENPBR_NO_FUZZ
  m.fuzz_weight = 0.0;
#endif
  float above = 1.0;
#ifndef OPENPBR_NO_FUZZ
  above -= m.fuzz_weight * albedoFuzzZeltner(nv, m.fuzz_roughness);
  fuzz = m.fuzz_weight * m.fuzz_color * fuzzZeltner(l, v, m.fuzz_roughness);
#endif
  vec3 below = vec3(above);
#ifndef OPENPBR_NO_COAT
  float cAlpha = m.coat_roughness * m.coat_roughness;
  float coatAlbedo = openPbrDielectricAlbedo(nv, cAlpha, m.coat_ior);
  float path = 0.5 * (1.0 / refractedCos(l.z, m.coat_ior) + 1.0 / refractedCos(nv, m.coat_ior));
  below *= mix(vec3(1.0), pow(m.coat_color, vec3(path)) * (1.0 - coatAlbedo), m.coat_weight)
    * openPbrCoatDarkening(m, nv);
  vec2 coatAlphas = anisotropicAlphas(cAlpha, m.coat_roughness_anisotropy, ANISOTROPY_OPENPBR);
  coat = vec3(m.coat_weight * fresnelDielectric(lh, m.coat_ior) * openPbrGgxLobe(l, v, h, coatAlphas) * above);
#endif
  float dielectric = 1.0 - m.base_metalness;
  float gloss = 1.0;
#ifndef OPENPBR_NO_SPECULAR
  float rBase = openPbrBaseRoughness(m);
  vec2 baseAlphas = anisotropicAlphas(rBase * rBase, m.specular_roughness_anisotropy, ANISOTROPY_OPENPBR);
  float lobe = openPbrGgxLobe(l, v, h, baseAlphas);
  float eta = openPbrSpecularEta(m);
  gloss -= openPbrDielectricAlbedo(nv, rBase * rBase, eta);
  specular = below * dielectric * m.specular_color * fresnelDielectric(lh, eta) * lobe;
  metal = below * m.base_metalness * m.specular_weight
    * fresnelF82Tint(m.base_weight * m.base_color, m.specular_color, lh) * lobe;
#endif
  float lv = dot(l, v);
  vec3 eon = vec3(diffuseEON(l.z, nv, lv, m.base_diffuse_roughness, m.base_color.r),
    diffuseEON(l.z, nv, lv, m.base_diffuse_roughness, m.base_color.g),
    diffuseEON(l.z, nv, lv, m.base_diffuse_roughness, m.base_color.b));
  diffuse = below * dielectric * gloss * m.base_weight * eon;
}

vec3 openPbrBRDF(vec3 l, vec3 v, OpenPbrMaterial m) {
  vec3 specular, diffuse, metal, coat, fuzz;
  openPbrLayers(l, v, m, specular, diffuse, metal, coat, fuzz);
  return specular + diffuse + metal + coat + fuzz;
}
