// A sphere of a measured (tabulated) BRDF under one punctual light: L = pi f c_light (n·l), view space.
#include "color.glsl"
#include "measured.glsl"

in vec3 vNormal;
in vec3 vViewPosition;
uniform vec3 uLightDir;
uniform float uExposure;
out vec4 fragColor;

void main() {
  vec3 n = normalize(vNormal);
  vec3 v = vec3(0.0, 0.0, 1.0); // orthographic camera
  vec3 l = normalize(uLightDir);
  vec3 radiance = PI * measuredBRDF(n, l, v) * max(dot(n, l), 0.0);
  fragColor = vec4(linearToSrgb(radiance * uExposure), 1.0);
}
