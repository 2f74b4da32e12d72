// A sphere of a measured (tabulated) BRDF under one punctual light: L = pi f c_light (n·l), view space,
// ray-traced on a quad (sphere-impostor.glsl).
#include "sphere-impostor.glsl"
#include "measured.glsl"

uniform vec3 uLightDir;
uniform float uExposure;
out vec4 fragColor;

void main() {
  SpherePixel pixel = spherePixel();
  vec3 n = pixel.n;
  vec3 v = vec3(0.0, 0.0, 1.0); // orthographic camera
  vec3 l = normalize(uLightDir);
  vec3 radiance = PI * measuredBRDF(n, l, v) * max(dot(n, l), 0.0);
  fragColor = overBackground(radiance * uExposure, pixel.coverage);
}
