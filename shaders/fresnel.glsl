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
