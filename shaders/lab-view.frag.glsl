// Shows a lab image: radiance scaled by the exposure and encoded as sRGB, or with ERROR_VIEW the absolute
// difference |a - b| (mean over RGB) on the viridis scale, 0 to uErrorScale, sphere pixels only. TANGENT_OVERLAY
// draws the tangent field's brushing lines over it (lab-tangent.glsl): a stroke along b in each of 14 × 14 cells.
#include "color.glsl"
#ifdef TANGENT_OVERLAY
#include "lab-tangent.glsl"
uniform float uExtent;
#endif
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

#ifdef TANGENT_OVERLAY
const float CELLS = 14.0;
// The stroke through this pixel's cell: 1 on its light core, 0.5 on its dark rim (legible on any radiance), else 0.
// The cell's normal is the sphere's at the cell's centre; b is drawn as the viewer sees it (foreshortened).
float brushStroke(vec2 uv) {
  vec2 centre = (floor(uv * CELLS) + 0.5) / CELLS;
  vec2 p = (2.0 * centre - 1.0) * uExtent;
  float r2 = dot(p, p);
  if (r2 >= 0.95) return 0.0;
  vec3 b = tangentFrame(vec3(p, sqrt(1.0 - r2)))[1];
  float len = length(b.xy);
  if (len < 1e-3) return 0.0;
  vec2 dir = b.xy / len;
  vec2 q = (uv - centre) * uRect.zw; // device pixels from the cell's centre
  float along = abs(dot(q, dir)) - 0.4 * len * uRect.z / CELLS;
  float across = abs(dot(q, vec2(-dir.y, dir.x)));
  float px = max(uRect.z / 300.0, 1.0);
  if (along < 0.0 && across < 0.8 * px) return 1.0;
  return along < px && across < 2.0 * px ? 0.5 : 0.0;
}
#endif

void main() {
  vec2 uv = (gl_FragCoord.xy - uRect.xy) / uRect.zw;
  vec4 a = texture(uImage, uv);
#ifdef ERROR_VIEW
  vec3 diff = abs(a.rgb - texture(uOther, uv).rgb);
  fragColor = a.a > 0.5 ? vec4(viridis((diff.r + diff.g + diff.b) / (3.0 * uErrorScale)), 1.0) : vec4(vec3(0.09), 1.0);
#else
  fragColor = vec4(linearToSrgb(a.rgb * uExposure), 1.0);
#endif
#ifdef TANGENT_OVERLAY
  float stroke = brushStroke(uv);
  if (stroke > 0.0) fragColor.rgb = stroke > 0.75 ? vec3(1.0, 0.85, 0.2) : vec3(0.0);
#endif
}
