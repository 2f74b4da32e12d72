// OpenPBR's base diffuse lobe, EON (Portsmouth, d'Eon et al. 2024), mirrors src/math/openpbr-diffuse.js (see there
// for the forms and their sources). roughness = base_diffuse_roughness in [0, 1]; nl, nv, lv = n·l, n·v, l·v.
#include "common.glsl"
#define FUJII_C1 (0.5 - 2.0 / (3.0 * PI))
#define FUJII_C2 (2.0 / 3.0 - 28.0 / (15.0 * PI))

// G(μ)/π of Fujii's exact albedo, 1 − sin³θ as cos²θ (1 + s + s²)/(1 + s): no 0/0 at grazing
float fujiiAlbedoG(float mu) {
  float c = saturate(mu);
  float s = sqrt(max((1.0 - c) * (1.0 + c), 0.0));
  float theta = acos(c);
  float g = s * (theta - s * c) + (2.0 / 3.0) * s * c * (1.0 + s + s * s) / (1.0 + s) - (2.0 / 3.0) * s;
  return g / PI;
}

float albedoFujiiOrenNayar(float mu, float roughness) {
  float r = saturate(roughness);
  return (1.0 + r * fujiiAlbedoG(mu)) / (1.0 + FUJII_C1 * r);
}

float averageAlbedoFujiiOrenNayar(float roughness) {
  float r = saturate(roughness);
  return (1.0 + FUJII_C2 * r) / (1.0 + FUJII_C1 * r);
}

float diffuseFujiiOrenNayar(float nl, float nv, float lv, float roughness) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  float r = saturate(roughness);
  float s = lv - nl * nv;
  float sOverT = s > 0.0 ? s / max(nl, nv) : s;
  return (1.0 + r * sOverT) / (PI * (1.0 + FUJII_C1 * r));
}

float diffuseEON(float nl, float nv, float lv, float roughness, float rho) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  float r = saturate(roughness);
  float p = saturate(rho);
  float a = 1.0 / (1.0 + FUJII_C1 * r);
  float avg = a * (1.0 + FUJII_C2 * r);
  float rhoMs = p * p * avg / (1.0 - p * (1.0 - avg));
  float lossL = FUJII_C1 - fujiiAlbedoG(nl);
  float ms = rhoMs * a * r * lossL * (FUJII_C1 - fujiiAlbedoG(nv)) / (PI * (FUJII_C1 - FUJII_C2));
  return p * diffuseFujiiOrenNayar(nl, nv, lv, r) + ms;
}
