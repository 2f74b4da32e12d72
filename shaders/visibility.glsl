// Geometry and visibility terms V = G / ((n·l)(n·v)), mirrors src/math/visibility.js.
#include "ndf.glsl"

bool aboveHorizon(float nl, float nv) { return nl > 0.0 && nv > 0.0; }

float visibilityImplicit(float nl, float nv) { return aboveHorizon(nl, nv) ? 1.0 : 0.0; }

float visibilityCookTorrance(float nl, float nv, float nh, float vh) {
  if (!aboveHorizon(nl, nv) || !(vh > 0.0) || !(nh > 0.0)) return 0.0;
  return min(1.0 / (nl * nv), min(2.0 * nh / (vh * nl), 2.0 * nh / (vh * nv)));
}

float visibilityKelemen(float lh) { return lh > 0.0 ? 1.0 / (lh * lh) : 0.0; }

// sqrt(c² + alpha² sin²): the root in every Smith GGX form
float ggxRoot(float c, float a2) { return sqrt(c * c + a2 * sin2FromCos(c)); }

float smithG1GGX(float cosTheta, float alpha) {
  if (!(cosTheta > 0.0)) return 0.0;
  float c = min(cosTheta, 1.0);
  float a = clampAlpha(alpha);
  return 2.0 * c / (c + ggxRoot(c, a * a));
}

// erfc for x >= 0: Abramowitz & Stegun 7.1.26 (absolute error < 1.5e-7), the float32 stand-in for the
// float64 erfc of src/math/special.js.
float erfcPositive(float x) {
  float t = 1.0 / (1.0 + 0.3275911 * x);
  float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  return poly * exp(-x * x);
}

// Beckmann's a = cot(theta)/alpha for G1; 1e30 stands for infinity at normal incidence (G1 = 1).
float beckmannSlopeRatio(float c, float alpha) {
  float s2 = sin2FromCos(c);
  return s2 == 0.0 ? 1e30 : c / (clampAlpha(alpha) * sqrt(s2));
}

float smithG1Beckmann(float cosTheta, float alpha) {
  if (!(cosTheta > 0.0)) return 0.0;
  float a = beckmannSlopeRatio(min(cosTheta, 1.0), alpha);
  if (a > 26.0) return 1.0;
  float lambda = (exp(-a * a) / (a * 1.7724538509055159) - erfcPositive(a)) / 2.0;
  return 1.0 / (1.0 + lambda);
}

float smithG1BeckmannWalter(float cosTheta, float alpha) {
  if (!(cosTheta > 0.0)) return 0.0;
  float a = beckmannSlopeRatio(min(cosTheta, 1.0), alpha);
  return a < 1.6 ? min((3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a), 1.0) : 1.0;
}

float visibilitySmithGGXSeparable(float nl, float nv, float alpha) {
  if (!aboveHorizon(nl, nv)) return 0.0;
  float l = min(nl, 1.0);
  float v = min(nv, 1.0);
  float a = clampAlpha(alpha);
  float a2 = a * a;
  return 4.0 / ((l + ggxRoot(l, a2)) * (v + ggxRoot(v, a2)));
}

float visibilitySmithGGXCorrelated(float nl, float nv, float alpha) {
  if (!aboveHorizon(nl, nv)) return 0.0;
  float l = min(nl, 1.0);
  float v = min(nv, 1.0);
  float a = clampAlpha(alpha);
  float a2 = a * a;
  return 2.0 / (l * ggxRoot(v, a2) + v * ggxRoot(l, a2));
}

float visibilitySmithGGXCorrelatedFast(float nl, float nv, float alpha) {
  if (!aboveHorizon(nl, nv)) return 0.0;
  float l = min(nl, 1.0);
  float v = min(nv, 1.0);
  float a = clampAlpha(alpha);
  return 2.0 / ((1.0 - a) * 2.0 * l * v + a * (l + v));
}

float visibilitySchlickGGX(float nl, float nv, float alpha) {
  if (!aboveHorizon(nl, nv)) return 0.0;
  float k = clampAlpha(alpha) / 2.0;
  return 1.0 / ((min(nl, 1.0) * (1.0 - k) + k) * (min(nv, 1.0) * (1.0 - k) + k));
}

float visibilitySmithBeckmannSeparable(float nl, float nv, float alpha) {
  if (!aboveHorizon(nl, nv)) return 0.0;
  return smithG1Beckmann(nl, alpha) * smithG1Beckmann(nv, alpha) / (min(nl, 1.0) * min(nv, 1.0));
}
