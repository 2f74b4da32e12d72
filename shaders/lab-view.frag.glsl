// Shows a lab image: radiance scaled by the exposure and encoded as sRGB, or with ERROR_VIEW the absolute
// difference |a - b| (mean over RGB) on the viridis scale, 0 to uErrorScale, sphere pixels only.
#include "color.glsl"
uniform sampler2D uImage;
uniform sampler2D uOther;
uniform vec4 uRect; // the panel in canvas pixels: x, y, width, height
uniform float uExposure;
uniform float uErrorScale;
out vec4 fragColor;

vec3 viridis(float t) { // a 5-stop fit of matplotlib's viridis, good to ~1/255
  t = clamp(t, 0.0, 1.0);
  vec3 c0 = vec3(0.267, 0.005, 0.329), c1 = vec3(0.229, 0.322, 0.546), c2 = vec3(0.128, 0.567, 0.551);
  vec3 c3 = vec3(0.369, 0.789, 0.383), c4 = vec3(0.993, 0.906, 0.144);
  float s = t * 4.0;
  return s < 1.0   ? mix(c0, c1, s)
         : s < 2.0 ? mix(c1, c2, s - 1.0)
         : s < 3.0 ? mix(c2, c3, s - 2.0)
                   : mix(c3, c4, s - 3.0);
}

void main() {
  vec2 uv = (gl_FragCoord.xy - uRect.xy) / uRect.zw;
  vec4 a = texture(uImage, uv);
#ifdef ERROR_VIEW
  vec3 diff = abs(a.rgb - texture(uOther, uv).rgb);
  fragColor = a.a > 0.5 ? vec4(viridis((diff.r + diff.g + diff.b) / (3.0 * uErrorScale)), 1.0) : vec4(vec3(0.09), 1.0);
#else
  fragColor = vec4(linearToSrgb(a.rgb * uExposure), 1.0);
#endif
}
