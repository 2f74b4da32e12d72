// Normal distribution functions, mirrors src/math/ndf.js (see there for the derivations).
#include "common.glsl"
#include "parameters.glsl"
float clampAlpha(float alpha) { return clamp(alpha, ALPHA_MIN, ALPHA_MAX); }

float ndfGGXFromSin2(float cosThetaM, float sin2ThetaM, float alpha) {
  if (!(cosThetaM > 0.0)) return 0.0;
  float c = min(cosThetaM, 1.0);
  float a = clampAlpha(alpha);
  float d = a * a * c * c + max(sin2ThetaM, 0.0);
  float t = a / d;
  return t * t / PI;
}
float ndfGGX(float cosThetaM, float alpha) {
  return ndfGGXFromSin2(cosThetaM, sin2FromCos(min(cosThetaM, 1.0)), alpha);
}

float log1pSmall(float x) {
  return abs(x) < 1e-2 ? x * (1.0 - x * (0.5 - x * (1.0 / 3.0 - x / 4.0))) : log(1.0 + x);
}

// float32 domain: p in [0, 1e30] (clamped), where (p + 2)/(2 pi) and a BRDF built on it stay finite. From n·m
// alone the lobe (about sqrt(2/p) wide) is resolved only for p up to ~1e6, for float32's n·m steps by 6e-8 near
// 1; ndfBlinnPhongFromSin2, from a half vector's sin²θm, resolves it up to p ~ 1e30 (sin² down to 1e-30).
#define BLINN_PHONG_MAX_EXPONENT 1e30
float ndfBlinnPhongFromSin2(float cosThetaM, float sin2ThetaM, float exponent) {
  if (!(cosThetaM > 0.0)) return 0.0;
  float p = clamp(exponent, 0.0, BLINN_PHONG_MAX_EXPONENT);
  float s2 = max(sin2ThetaM, 0.0);
  float lnC = s2 < 0.5 ? log1pSmall(-s2) / 2.0 : log(min(cosThetaM, 1.0));
  return (p + 2.0) / (2.0 * PI) * exp(p * lnC);
}
float ndfBlinnPhong(float cosThetaM, float exponent) {
  return ndfBlinnPhongFromSin2(cosThetaM, sin2FromCos(min(cosThetaM, 1.0)), exponent);
}

float ndfBeckmannFromSin2(float cosThetaM, float sin2ThetaM, float alpha) {
  if (!(cosThetaM > 0.0)) return 0.0;
  float c = min(cosThetaM, 1.0);
  float a = clampAlpha(alpha);
  float a2 = a * a;
  float c2 = c * c;
  float s2 = max(sin2ThetaM, 0.0);
  // compared before dividing: c² alpha² underflows to 0 for cos below ~1e-15 (flushed, as GPUs may), and GLSL ES
  // 3.00 leaves x / 0 unspecified
  if (s2 > 80.0 * c2 * a2) return 0.0;
  return exp(-s2 / (c2 * a2)) / (PI * a2 * c2 * c2);
}
float ndfBeckmann(float cosThetaM, float alpha) {
  return ndfBeckmannFromSin2(cosThetaM, sin2FromCos(min(cosThetaM, 1.0)), alpha);
}

float expm1OverX(float x) {
  return abs(x) < 1e-2 ? 1.0 + x / 2.0 + x * x / 6.0 + x * x * x / 24.0 : (exp(x) - 1.0) / x;
}
#define ABC_SERIES_TERMS 40
float abcNormalization(float a1, float a2) {
  if (a1 * (a2 + 1.0) <= 1.0) {
    float term = 1.0;
    float sum = 0.0;
    for (int k = 0; k < ABC_SERIES_TERMS; k++) {
      float fk = float(k);
      sum += term / ((fk + 1.0) * (fk + 2.0));
      term *= -(a2 + fk) * a1 / (fk + 1.0);
    }
    return sum;
  }
  float L = log(1.0 + a1);
  return L * ((1.0 + a1) * expm1OverX((1.0 - a2) * L) - expm1OverX((2.0 - a2) * L)) / (a1 * a1);
}
float ndfABC(float cosThetaM, float a1, float a2) {
  if (!(cosThetaM > 0.0)) return 0.0;
  float b = clamp(a1, 0.01, 1e4);
  float cc = clamp(a2, 0.05, 20.0);
  float c = min(cosThetaM, 1.0);
  return pow(1.0 + b * (1.0 - c), -cc) / (2.0 * PI * abcNormalization(b, cc));
}

// The normaliser Γ(1 - p, alpha) depends on the parameters alone: it comes in precomputed (float64, in JS:
// the SGD entry's normaliser in src/math/catalogue/ndf-terms.js, as uSgdNorm), not integrated at every pixel.
float ndfSGD(float cosThetaM, float alpha, float p, float norm) {
  if (!(cosThetaM > 0.0)) return 0.0;
  float a = clamp(alpha, 0.01, 2.0);
  float q = clamp(p, 0.0, 1.9);
  float c = min(cosThetaM, 1.0);
  float c2 = c * c;
  float s2 = sin2FromCos(c);
  if (s2 > (80.0 - a) * c2 * a) return 0.0; // y > 80, compared before dividing (c² a underflows below cos ~1e-19)
  float y = a + s2 / (c2 * a);
  return exp(-y) * pow(y, -q) / (a * norm * PI * c2 * c2);
}
