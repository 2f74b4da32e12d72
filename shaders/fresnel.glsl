// Fresnel reflectance, mirrors src/math/fresnel.js function by function (see there for the derivations).
#include "common.glsl"

float fresnelSchlick(float f0, float cosTheta) {
  float m = 1.0 - saturate(cosTheta);
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}
vec3 fresnelSchlick(vec3 f0, float cosTheta) {
  float m = 1.0 - saturate(cosTheta);
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

float fresnelSchlickSG(float f0, float cosTheta) {
  float c = saturate(cosTheta);
  return f0 + (1.0 - f0) * exp2((-5.55473 * c - 6.98316) * c);
}

float fresnelDielectric(float cosThetaI, float eta) {
  float c = saturate(cosThetaI);
  float e2m1 = (eta - 1.0) * (eta + 1.0);
  if (e2m1 == 0.0) return 0.0;
  float g2 = e2m1 + c * c;
  if (g2 <= 0.0) return 1.0;
  float g = sqrt(g2);
  float rs = -e2m1 / ((g + c) * (g + c));
  float pd = eta * eta * c + g;
  float rp = e2m1 * ((eta * eta + 1.0) * c * c - 1.0) / (pd * pd);
  return min(0.5 * (rs * rs + rp * rp), 1.0);
}

float fresnelConductor(float cosThetaI, float eta, float k) {
  float c = saturate(cosThetaI);
  float c2 = c * c;
  float sin2 = sin2FromCos(c);
  float e2m1 = (eta - 1.0) * (eta + 1.0);
  float ek2 = 4.0 * eta * eta * k * k;
  float x = e2m1 - k * k + c2;
  float s = sqrt(x * x + ek2);
  float a2, b2, a2mc2;
  if (x > 0.0) {
    b2 = ek2 / (2.0 * (s + x));
    a2 = x + b2;
    a2mc2 = e2m1 - k * k + b2;
  } else {
    a2 = s - x > 0.0 ? ek2 / (2.0 * (s - x)) : 0.0;
    b2 = a2 - x;
    a2mc2 = a2 - c2;
  }
  float a = sqrt(a2);
  float amc = a + c > 0.0 ? a2mc2 / (a + c) : 0.0;
  float sDen = (a + c) * (a + c) + b2;
  if (sDen == 0.0) return 0.0;
  float rs = (amc * amc + b2) / sDen;
  float ac = a * c;
  float pNum = (ac - sin2) * (ac - sin2) + b2 * c2;
  float pDen = (ac + sin2) * (ac + sin2) + b2 * c2;
  float rp = pDen > 0.0 ? rs * pNum / pDen : rs;
  return min(0.5 * (rs + rp), 1.0);
}
vec3 fresnelConductor(float cosThetaI, vec3 eta, vec3 k) {
  return vec3(fresnelConductor(cosThetaI, eta.r, k.r), fresnelConductor(cosThetaI, eta.g, k.g),
              fresnelConductor(cosThetaI, eta.b, k.b));
}

// F82-tint (Hoffman 2023; OpenPBR Surface's metal): Schlick minus b μ (1 − μ)⁶, with b such that
// F(1/7) = tint · Schlick(f0, 1/7). F82_NORM = 1 / (μ̄ (1 − μ̄)⁶) = 7⁷ / 6⁶. Clamped to [0, 1] (src/math/fresnel.js).
const float F82_MU = 1.0 / 7.0;
const float F82_NORM = 823543.0 / 46656.0;
float fresnelF82Tint(float f0, float tint, float cosTheta) {
  float f = saturate(f0);
  float c = saturate(cosTheta);
  float m = 1.0 - c;
  float m3 = m * m * m;
  float b = fresnelSchlick(f, F82_MU) * (1.0 - saturate(tint)) * F82_NORM;
  return saturate(fresnelSchlick(f, c) - b * c * m3 * m3);
}
vec3 fresnelF82Tint(vec3 f0, vec3 tint, float cosTheta) {
  vec3 f = clamp(f0, 0.0, 1.0);
  float c = saturate(cosTheta);
  float m = 1.0 - c;
  float m3 = m * m * m;
  vec3 b = fresnelSchlick(f, F82_MU) * (1.0 - clamp(tint, 0.0, 1.0)) * F82_NORM;
  return clamp(fresnelSchlick(f, c) - b * c * m3 * m3, 0.0, 1.0);
}
// (f0, tint) of F82-tint fitted to a conductor: exact at θ = 0 and at acos(1/7)
vec2 f82TintFromConductor(float eta, float k) {
  float f0 = fresnelConductor(1.0, eta, k);
  return vec2(f0, fresnelConductor(F82_MU, eta, k) / fresnelSchlick(f0, F82_MU));
}
