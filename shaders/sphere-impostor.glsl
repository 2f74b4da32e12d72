// The unit sphere ray-traced on a quad (sphere-impostor.vert.glsl) under an orthographic camera looking down -z
// (view direction (0, 0, 1)): the exact normal under each pixel, and the part of the pixel the silhouette covers,
// for an antialiased edge without multisampling. The sphere is blended over uBackground by that coverage.
#include "color.glsl"

in vec2 vSphere; // the pixel centre, in the sphere's units
uniform vec3 uBackground; // linear RGB

// The area of a unit pixel on the inner side of a straight edge at signed distance s from its centre (in pixels,
// > 0 inside) with unit normal e: a line cutting a square. The silhouette is a circle many pixels wide: straight
// across one pixel.
float edgeCoverage(float s, vec2 e) {
  float a = max(abs(e.x), abs(e.y));
  float b = min(abs(e.x), abs(e.y));
  float u = s + 0.5 * (a + b); // how far the edge has swept over the pixel along e: 0 to a + b
  if (u <= 0.0) return 0.0;
  if (u >= a + b) return 1.0;
  if (u < b) return u * u / (2.0 * a * b); // a corner triangle
  if (u > a) return 1.0 - (a + b - u) * (a + b - u) / (2.0 * a * b); // all but the opposite corner
  return (u - 0.5 * b) / a; // a trapezoid
}

struct SpherePixel {
  vec3 n; // the normal where the pixel is shaded
  float coverage; // the part of the pixel inside the silhouette
};

// The sphere under this fragment's pixel; a pixel the silhouette misses is discarded (the background is there).
SpherePixel spherePixel() {
  float r = length(vSphere);
  float pixel = length(dFdx(vSphere)); // the sphere's units per pixel
  float s = (1.0 - r) / pixel;
  // half a pixel's diagonal is under 1: beyond, the pixel is all in or all out (and the edge's normal is not needed)
  float coverage = s >= 1.0 ? 1.0 : s <= -1.0 ? 0.0 : edgeCoverage(s, vSphere / r);
  if (coverage <= 0.0) discard;
  // a pixel the silhouette cuts is shaded at the middle of the part it covers, from the edge to s + 1/2 pixels in
  // (but not on the edge, where n·v = 0): n·v changes fast there, and the pixel centre may be outside
  float rs = s >= 0.5 ? r : 1.0 - pixel * max(0.5 * (s + 0.5), 0.1);
  vec2 xy = s >= 0.5 ? vSphere : vSphere * (rs / r); // (r = 0 at the centre)
  // 1 - r² as (1 - r)(1 + r): no cancellation near the silhouette
  return SpherePixel(vec3(xy, sqrt(max(sin2FromCos(rs), 0.0))), coverage);
}

// The pixel's colour: the covered part the sphere's radiance (shown up to 1), the rest the background, added as
// light and then encoded as sRGB.
vec4 overBackground(vec3 radiance, float coverage) {
  return vec4(linearToSrgb(mix(uBackground, saturate(radiance), coverage)), 1.0);
}
