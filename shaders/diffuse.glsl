// Diffuse terms, mirrors src/math/diffuse.js (see there for the forms and sources).
#include "fresnel.glsl"

// cos of the azimuth between l and v about n = z; 1 where either lies along n (no term depends on it there),
// as cosPhiDiff of src/widgets/diffuse-explorer/model.js
float cosPhiDiff(vec3 l, vec3 v) {
  float d = dot(l.xy, l.xy) * dot(v.xy, v.xy);
  return d > 1e-12 ? dot(l.xy, v.xy) / sqrt(d) : 1.0;
}

float diffuseLambert(float cdiff) { return saturate(cdiff) / PI; }

float diffuseFresnelWeighted(float nl, float nv, float f0, float cdiff) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  return (1.0 - fresnelSchlick(f0, nl)) * (1.0 - fresnelSchlick(f0, nv)) * diffuseLambert(cdiff);
}

float ashikhminShirleyFactor(float c) {
  float m = 1.0 - min(c, 1.0) / 2.0;
  float m2 = m * m;
  return 1.0 - m2 * m2 * m;
}
float diffuseAshikhminShirley(float nl, float nv, float f0, float cdiff) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  return 28.0 / (23.0 * PI) * saturate(cdiff) * (1.0 - saturate(f0)) * ashikhminShirleyFactor(nl) *
         ashikhminShirleyFactor(nv);
}

float diffuseOrenNayar(float nl, float nv, float cosPhiDiff, float sigma, float cdiff) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  float s2 = sigma * sigma;
  float c = saturate(cdiff);
  float cp = clamp(cosPhiDiff, -1.0, 1.0);
  float cosA = min(min(nl, nv), 1.0);
  float cosB = min(max(nl, nv), 1.0);
  float sinA = sqrt(sin2FromCos(cosA));
  float sinB = sqrt(sin2FromCos(cosB));
  // The angles through atan, not acos/asin: GPUs may evaluate asin(x) as pi/2 - sqrt(1 - x)·P(x) (Mesa's llvmpipe
  // does), so float32's rounding near pi/2 is left as an absolute error: asin(1e-7) came out 19 % off, and below
  // u multiplies tan b ~ 1/cos b (relative error up to 1 at cos = 1e-7). atan is evaluated as x·P(x²) after range
  // reduction (2e-5 relative there), and asin(c) = atan(c, sqrt(1 - c²)) with both arguments from the cosine.
  float a = atan(sinA, cosA);
  float b = atan(sinB, cosB);
  float tanB = sinB / cosB;
  float tanHalfSum = (sinA + sinB) / (cosA + cosB);
  float C1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
  float u = 2.0 / PI * atan(cosB, sinB); // 1 - 2b/pi without cancellation
  float t = 1.0 - u;
  float sinAMinusT3 = -(cosA * cosA) / (1.0 + sinA) + u * (1.0 + t + t * t);
  float C2 = 0.45 * s2 / (s2 + 0.09) * (cp >= 0.0 ? sinA : sinAMinusT3);
  float r = 4.0 * a * b / (PI * PI);
  float C3 = 0.125 * s2 / (s2 + 0.09) * r * r;
  float L1 = c / PI * (C1 + cp * C2 * tanB + (1.0 - abs(cp)) * C3 * tanHalfSum);
  float L2 = 0.17 * c * c / PI * (s2 / (s2 + 0.13)) * (1.0 - cp + cp * u * (1.0 + t));
  return max(L1 + L2, 0.0);
}

float diffuseOrenNayarQualitative(float nl, float nv, float cosPhiDiff, float sigma, float cdiff) {
  if (!(nl > 0.0 && nv > 0.0)) return 0.0;
  float s2 = sigma * sigma;
  float lo = min(min(nl, nv), 1.0);
  float hi = min(max(nl, nv), 1.0);
  float sinA = sqrt(sin2FromCos(lo));
  float tanB = sqrt(sin2FromCos(hi)) / hi;
  float A = 1.0 - 0.5 * s2 / (s2 + 0.33);
  float B = 0.45 * s2 / (s2 + 0.09);
  return saturate(cdiff) / PI * (A + B * max(cosPhiDiff, 0.0) * sinA * tanB);
}
