// sRGB transfer functions (IEC 61966-2-1), mirrors src/math/color.js.
#include "common.glsl"
float srgbToLinear(float c) {
  float x = saturate(c);
  return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}
float linearToSrgb(float c) {
  float x = saturate(c);
  return x <= 0.0031308 ? x * 12.92 : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}
vec3 linearToSrgb(vec3 c) { return vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)); }
