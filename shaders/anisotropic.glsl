// Anisotropic microfacets, mirrors src/math/anisotropic.js (see there for the forms and their sources).
// Frame x = t, y = b, z = n; h, w, l, v unit vectors; alpha = (alphaX, alphaY). float32: sin² and the azimuth come
// from the components (no 1 - cos²), every sum is of positive terms, and a division is guarded or has a divisor
// bounded away from 0 by the clamp of alpha.
#include "visibility.glsl"
#define ALPHA_ANISO_MAX 4.0
vec2 clampAlphaAniso(vec2 alpha) { return clamp(alpha, ALPHA_MIN, ALPHA_ANISO_MAX); }

// hx/αx, hy/αy are at most 1e4 (alpha >= 1e-4), so d <= 2e8 and d² stays far inside float32
float ndfGGXAniso(vec3 h, vec2 alpha) {
  if (!(h.z > 0.0)) return 0.0;
  vec2 a = clampAlphaAniso(alpha);
  vec2 s = h.xy / a;
  float d = dot(s, s) + h.z * h.z;
  return 1.0 / (PI * a.x * a.y * d * d);
}

// compared before dividing (a grazing h's hz⁴ underflows float32, and GLSL ES 3.00 leaves x / 0 unspecified):
// where the exponent is above -80, q >= (1 - hz²)/16 gives hz² >= 1/1281, and hz⁴ is safe
float ndfBeckmannAniso(vec3 h, vec2 alpha) {
  if (!(h.z > 0.0)) return 0.0;
  vec2 a = clampAlphaAniso(alpha);
  vec2 s = h.xy / a;
  float q = dot(s, s);
  float c2 = h.z * h.z;
  if (q > 80.0 * c2) return 0.0;
  return exp(-q / c2) / (PI * a.x * a.y * c2 * c2);
}

// sqrt(wz² + αx² wx² + αy² wy²) = wz (1 + 2Λ(w)) for GGX
float ggxAnisoRoot(vec3 w, vec2 a) {
  vec2 p = a * w.xy;
  return sqrt(w.z * w.z + dot(p, p));
}

float smithG1GGXAniso(vec3 w, vec2 alpha) {
  if (!(w.z > 0.0)) return 0.0;
  return 2.0 * w.z / (w.z + ggxAnisoRoot(w, clampAlphaAniso(alpha)));
}

// a = wz / (α(φ) sin θ), compared with 26 before dividing (G1 = 1 along n, where the projected roughness is 0)
float smithG1BeckmannAniso(vec3 w, vec2 alpha) {
  if (!(w.z > 0.0)) return 0.0;
  vec2 p = clampAlphaAniso(alpha) * w.xy;
  float r = sqrt(dot(p, p));
  if (!(w.z < 26.0 * r)) return 1.0;
  float a = w.z / r;
  float lambda = (exp(-a * a) / (a * 1.7724538509055159) - erfcPositive(a)) / 2.0;
  return 1.0 / (1.0 + lambda);
}

float visibilitySmithGGXCorrelatedAniso(vec3 l, vec3 v, vec2 alpha) {
  if (!aboveHorizon(l.z, v.z)) return 0.0;
  vec2 a = clampAlphaAniso(alpha);
  return 2.0 / (v.z * ggxAnisoRoot(l, a) + l.z * ggxAnisoRoot(v, a));
}

// The catalogue's forms (src/math/catalogue: ggxAniso, beckmannAniso, smithGGXCorrelatedAniso): the same functions
// over the components, as the JS twins and the dispatch (ndfTerm, visibilityTerm) pass them
float ndfGGXAniso(float hx, float hy, float hz, float ax, float ay) {
  return ndfGGXAniso(vec3(hx, hy, hz), vec2(ax, ay));
}
float ndfBeckmannAniso(float hx, float hy, float hz, float ax, float ay) {
  return ndfBeckmannAniso(vec3(hx, hy, hz), vec2(ax, ay));
}
float visibilitySmithGGXCorrelatedAniso(
  float lx, float ly, float lz, float vx, float vy, float vz, float ax, float ay) {
  return visibilitySmithGGXCorrelatedAniso(vec3(lx, ly, lz), vec3(vx, vy, vz), vec2(ax, ay));
}

// the conventions of anisotropicAlphas (JS: 'burley2012', 'gltf', 'openpbr'); alpha = r² of each model
#define ANISOTROPY_BURLEY2012 0
#define ANISOTROPY_GLTF 1
#define ANISOTROPY_OPENPBR 2
vec2 anisotropicAlphas(float alpha, float anisotropy, int convention) {
  float a = clamp(anisotropy, 0.0, 1.0);
  if (convention == ANISOTROPY_BURLEY2012) {
    float aspect = sqrt(1.0 - 0.9 * a);
    return vec2(alpha / aspect, alpha * aspect);
  }
  if (convention == ANISOTROPY_GLTF) return vec2(mix(alpha, 1.0, a * a), alpha);
  float at = alpha * sqrt(2.0 / (1.0 + (1.0 - a) * (1.0 - a)));
  return vec2(at, (1.0 - a) * at);
}

// Visible normals from v (Dupuy & Benyoub 2023's spherical caps), u.x in [0, 1) the cap height, u.y the azimuth
// from v''s own; the sums in the forms that do not cancel (see the JS twin), so the GPU's cos(π u.y) enters squared
// where c + v' nearly vanishes (the rim, u.x -> 1)
vec3 sampleVisibleNormalGGXAniso(vec3 v, vec2 alpha, vec2 u) {
  vec2 a = clampAlphaAniso(alpha);
  vec3 wi = normalize(vec3(a * v.xy, v.z));
  float w1 = 1.0 + wi.z;
  float rho2 = dot(wi.xy, wi.xy);
  float rho = sqrt(rho2);
  vec2 e = rho > 0.0 ? wi.xy / rho : vec2(1.0, 0.0);
  float sinC = sqrt(u.x * (rho2 + (1.0 - u.x) * w1 * w1));
  float rs = rho + sinC;
  float rhoMinusSin = rs > 0.0 ? (1.0 - u.x) * (rho2 - u.x * w1 * w1) / rs : 0.0;
  float c = sin(PI * (0.5 - u.y)); // cos(π u.y), exactly 0 at u.y = 0.5 (see the JS twin)
  float s = sin(PI * min(u.y, 1.0 - u.y));
  float cosPsi = (c - s) * (c + s);
  float along = cosPsi >= 0.0 ? rho + sinC * cosPsi : rhoMinusSin + 2.0 * sinC * c * c;
  float across = 2.0 * sinC * s * c;
  vec3 h = vec3(a * (along * e + across * vec2(-e.y, e.x)), (1.0 - u.x) * w1);
  float m = length(h);
  return m > 0.0 ? h / m : vec3(0.0, 0.0, 1.0);
}

// G1(v) max(0, v·m) D(m) / vz, with G1 / vz = 2 / (vz + root): nothing small divides at grazing v
float visibleNormalPdfGGXAniso(vec3 v, vec3 m, vec2 alpha) {
  float vm = dot(v, m);
  if (!(v.z > 0.0) || !(vm > 0.0)) return 0.0;
  return 2.0 * vm * ndfGGXAniso(m, alpha) / (v.z + ggxAnisoRoot(v, clampAlphaAniso(alpha)));
}

// per steradian of l, the mirror of v about m: G1(v) D(m) / (4 vz)
float reflectedPdfGGXAniso(vec3 v, vec3 m, vec2 alpha) {
  if (!(v.z > 0.0) || !(dot(v, m) > 0.0)) return 0.0;
  return ndfGGXAniso(m, alpha) / (2.0 * (v.z + ggxAnisoRoot(v, clampAlphaAniso(alpha))));
}

// The bent reflection vector of Filament's and three.js's anisotropic IBL (JS twin: anisotropicBentReflection): the
// grain is b for a >= 0 and t for a < 0; v less its part along it is mixed into n with weight (1 - |a| (1 - √α))⁴
// and v mirrored about the result; v along the grain gives the mirror about n
vec3 anisotropicBentReflection(vec3 v, float alpha, float anisotropy) {
  float a = clamp(anisotropy, -1.0, 1.0);
  vec3 across = a >= 0.0 ? vec3(v.x, 0.0, v.z) : vec3(0.0, v.y, v.z);
  if (dot(across, across) < 1e-12) return reflect(-v, vec3(0.0, 0.0, 1.0));
  float k = 1.0 - abs(a) * (1.0 - sqrt(clamp(alpha, 0.0, 1.0)));
  float toN = k * k * k * k;
  vec3 bent = normalize(mix(normalize(across), vec3(0.0, 0.0, 1.0), toN));
  return reflect(-v, bent);
}
