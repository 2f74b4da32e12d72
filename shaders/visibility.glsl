// Visibility terms V = G / ((n·l)(n·v)), mirrors src/math/visibility.js.
#include "ndf.glsl"

float visibilitySmithGGXCorrelated(float nl, float nv, float alpha) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  float l = min(nl, 1.0);
  float v = min(nv, 1.0);
  float a = clampAlpha(alpha);
  float a2 = a * a;
  float lambdaV = l * sqrt(v * v + a2 * sin2FromCos(v));
  float lambdaL = v * sqrt(l * l + a2 * sin2FromCos(l));
  return 2.0 / (lambdaV + lambdaL);
}
