// One sample per pixel of light through boxes of a homogeneous medium, added to the running sum in uPrev.
// A grid of CELLS_X x CELLS_Y glasses, each a cube of unit depth seen head-on, with its own absorption and
// scattering (per RGB channel, already multiplied by the physical depth). Absorption is applied exactly, as
// the weight exp(-sigma_a L) over the path length L (Beer-Lambert); only scattering is sampled, with spectral
// MIS: each path draws its free flights with one channel's scattering coefficient, and every channel is
// weighted by its own path pdf over the mean of the three, so the weights stay below 3 exp(-sigma_a L) and
// colours do not speckle. Directions follow an isotropic phase function; Russian roulette after 32 events
// keeps long walks (milk) unbiased. A pure absorber renders exactly, without noise.
#include "media.glsl"
uniform sampler2D uPrev;
uniform vec2 uSize;
uniform float uFrame;
uniform vec3 uSigmaA[CELLS];
uniform vec3 uSigmaS[CELLS];
out vec4 fragColor;

uint hashState;
float rand() {
  hashState = hashState * 747796405u + 2891336453u;
  uint w = ((hashState >> ((hashState >> 28u) + 4u)) ^ hashState) * 277803737u;
  return uniformFromBits((w >> 22u) ^ w);
}

// The surroundings: a chequered wall behind the glasses, a bright sky above, a dim floor below.
vec3 environment(vec3 o, vec3 d) {
  if (d.z < -1e-4) {
    vec3 p = o + d * ((-1.0 - o.z) / d.z);
    float check = mod(floor(p.x * 6.0) + floor(p.y * 6.0), 2.0);
    return vec3(mix(0.35, 0.9, check));
  }
  return vec3(mix(0.2, 1.4, smoothstep(-0.3, 0.7, d.y)));
}

// where the ray leaves the cube [-0.5, 0.5]^3 (t of exit), assuming it starts inside; an axis the ray does
// not move along never bounds it
float exitDistance(vec3 o, vec3 d) {
  vec3 t = vec3(1e30);
  if (d.x != 0.0) t.x = (sign(d.x) * 0.5 - o.x) / d.x;
  if (d.y != 0.0) t.y = (sign(d.y) * 0.5 - o.y) / d.y;
  if (d.z != 0.0) t.z = (sign(d.z) * 0.5 - o.z) / d.z;
  return max(min(t.x, min(t.y, t.z)), 0.0);
}

void main() {
  vec2 pixel = gl_FragCoord.xy;
  hashState = uint(pixel.x) * 1973u + uint(pixel.y) * 9277u + uint(uFrame) * 26699u + 1u;
  vec2 cells = vec2(CELLS_X, CELLS_Y);
  vec2 q = (pixel + vec2(rand(), rand())) / uSize * cells;
  vec2 cell = floor(q);
  int index = int(cell.y) * CELLS_X + int(cell.x);
  vec2 local = (fract(q) - 0.5) * 1.25; // the cube fills 80% of its cell
  vec3 o = vec3(local, 0.5);
  vec3 d = vec3(0.0, 0.0, -1.0);
  vec3 radiance;
  if (abs(local.x) > 0.5 || abs(local.y) > 0.5) {
    radiance = environment(vec3(local, 0.0), d);
  } else {
    vec3 sa = uSigmaA[index];
    vec3 ss = uSigmaS[index];
    int hero = min(int(rand() * 3.0), 2);
    float ssHero = ss[hero];
    vec3 logPdf = vec3(0.0); // log of each channel's pdf of the sampled path (scattering only)
    float pathLength = 0.0;
    float roulette = 1.0;
    radiance = vec3(0.0);
    for (int bounce = 0; bounce < 512; bounce++) {
      float tExit = exitDistance(o, d);
      float t = ssHero > 0.0 ? -log(1.0 - rand()) / ssHero : 1e30;
      if (t >= tExit) {
        logPdf -= ss * tExit;
        pathLength += tExit;
        vec3 mis = 3.0 / vec3(dot(exp(logPdf - logPdf.r), vec3(1.0)), dot(exp(logPdf - logPdf.g), vec3(1.0)),
                              dot(exp(logPdf - logPdf.b), vec3(1.0)));
        radiance = roulette * mis * transmittance(sa, pathLength) * environment(o + d * tExit, d);
        break;
      }
      logPdf += log(max(ss, vec3(1e-30))) - ss * t;
      pathLength += t;
      o += d * t;
      float z = 2.0 * rand() - 1.0;
      float phi = 2.0 * PI * rand();
      d = vec3(sqrt(1.0 - z * z) * vec2(cos(phi), sin(phi)), z);
      if (bounce >= 32) {
        if (rand() > 0.95) break;
        roulette /= 0.95;
      }
    }
  }
  fragColor = texelFetch(uPrev, ivec2(pixel), 0) + vec4(radiance, 1.0);
}
