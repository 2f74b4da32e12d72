// Normal distribution functions, mirrors src/math/ndf.js.
#include "common.glsl"
#define ALPHA_MIN 1e-4
float clampAlpha(float alpha) { return clamp(alpha, ALPHA_MIN, 1.0); }

float ndfGGX(float cosThetaM, float alpha) {
  if (!(cosThetaM > 0.0)) return 0.0;
  float c = min(cosThetaM, 1.0);
  float a = clampAlpha(alpha);
  float d = a * a * c * c + sin2FromCos(c);
  float t = a / d;
  return t * t / PI;
}
