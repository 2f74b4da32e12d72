// The material lab's reference: the reflectance equation by Monte Carlo, uSamples samples per pixel and light in
// one batch, each pixel's pattern shifted (uJitter plus a hash), the batches averaged into a running mean
// (uPrevious, weighted uWeight). The punctual light needs no samples: it is exact in both images.
#include "lab-surround.glsl"
#include "lab-lobe-sampling.glsl"
#include "env-sampling.glsl"
#include "lab-light-sphere-pars.glsl"

uniform bool uEnvSampling;
uniform vec2 uJitter;
uniform sampler2D uPrevious;
uniform float uWeight;

// Per-pixel offset of the sample pattern (a hash), so neighbouring pixels do not share one pattern.
vec2 pixelHash(vec2 p) {
  vec3 q = fract(vec3(p.xyx) * vec3(0.1031, 0.1030, 0.0973));
  q += dot(q, q.yzx + 33.33);
  return fract((q.xx + q.yz) * q.zy);
}

vec2 referenceShift() { return fract(uJitter + pixelHash(gl_FragCoord.xy)); }

// This batch's radiance added to the mean of the batches before it.
vec3 runningMean(vec3 batch) { return mix(texelFetch(uPrevious, ivec2(gl_FragCoord.xy), 0).rgb, batch, uWeight); }

// The sphere light by uniform samples of its cone: pdf 1/(2 pi (1 - cos theta_s)).
vec3 evaluateReferenceSphereLight(mat3 toLocal, vec3 v, vec2 shift) {
  int n = uSamples;
  float cosMax = sqrt(max(1.0 - uSphereSin * uSphereSin, 0.0));
  mat3 coneToWorld = frameAround(uSphereDir);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec3 l = toLocal * (coneToWorld * sampleCone(fract(hammersley(i, n) + shift), cosMax));
    sum += brdfTotal(l, v) * max(l.z, 0.0);
  }
  return sum * uSphereRadiance * (2.0 * PI * (1.0 - cosMax)) / float(n);
}

// One sample from each of three strategies (the lobe, cosine, the map's brightness), weighted by the balance
// heuristic: each contributes f (n·l) L / (sum of the three densities at its direction).
vec3 referenceSample(vec3 l, vec3 v, mat3 toWorld) {
  if (l.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + v);
  float pdf = lobeReflectedPdf(v, h) + l.z / PI;
  vec3 dWorld = toWorld * l;
  if (uEnvSampling) pdf += environmentMapPdf(dWorld);
  return brdfTotal(l, v) * l.z * surroundRadiance(dWorld) / max(pdf, 1e-30);
}

// The environment and ambient light together, by multiple importance sampling.
vec3 evaluateReferenceSurround(mat3 toWorld, mat3 toLocal, vec3 v, vec2 shift) {
  int n = uSamples;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; i++) {
    vec2 u = fract(hammersley(i, n) + shift);
    vec3 m = lobeNormal(v, u);
    sum += referenceSample(2.0 * dot(v, m) * m - v, v, toWorld);
    sum += referenceSample(sampleCosine(u.yx), v, toWorld);
    if (uEnvSampling) sum += referenceSample(toLocal * sampleEnvironmentMap(u), v, toWorld);
  }
  return sum / float(n);
}
