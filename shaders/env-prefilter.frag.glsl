// Prefilters the environment for the split sum (Karis 2013): each texel, a direction N, averages the map over
// the chosen NDF's lobe around N (brdf.glsl's switch: GGX, or Beckmann with NDF_BECKMANN) with n = v = r,
// weighted by n·l. Samples read a coarser mip where each covers more of
// the sphere (filtered importance sampling), so few samples do not alias; the mips are of the solid-angle
// weighted map (env-copy WEIGHTED), so a coarse texel near a pole carries no more light than it should.
#include "ndf-sampling.glsl"
#include "env.glsl"
uniform sampler2D uEnv;
uniform vec2 uEnvSize;
uniform vec2 uSize;
uniform float uAlpha;
uniform int uSamples;
out vec4 fragColor;

float lodFor(float pdf) {
  float texel = 4.0 * PI / (uEnvSize.x * uEnvSize.y);
  return max(0.5 * log2(1.0 / (float(uSamples) * max(pdf, 1e-8) * texel)) + 1.0, 0.0);
}

void main() {
  vec3 n = equirectDirection(gl_FragCoord.xy / uSize);
  mat3 toWorld = frameAround(n);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int i = 0; i < uSamples; i++) {
    vec2 u = hammersley(i, uSamples);
    vec3 m = sampleLobeNormal(u, uAlpha);
    vec3 l = 2.0 * m.z * m - vec3(0.0, 0.0, 1.0);
    if (l.z <= 0.0) continue;
    float pdf = reflectedPdf(m, m.z, uAlpha); // v = n: v·m = n·m
    float w = l.z;
    vec4 c = textureLod(uEnv, equirectUv(toWorld * l), lodFor(pdf));
    sum += w * c.rgb / max(c.a, 1e-6);
    weight += w;
  }
  fragColor = vec4(sum / max(weight, 1e-8), 1.0);
}
