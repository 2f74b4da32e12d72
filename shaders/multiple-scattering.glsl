// Energy compensation for multiple scattering, mirrors src/math/multiple-scattering.js (see there for the
// derivations). References:
//   [1] Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks" (SIGGRAPH course notes)
//   [2] Turquin 2019, "Practical multiple scattering compensation for microfacet models"
// The energy lost, 1 - E(mu, alpha) and 1 - E_avg(alpha) (GGX, height-correlated Smith, F = 1), comes from a
// table computed in float64 (src/math/albedo-table.js), bound as uAlbedoTableGGX when ALBEDO_TABLE_GGX is defined.
#include "common.glsl"

// The cosine-weighted average of Schlick's Fresnel: f0 + (1 - f0)/21 [1].
float fresnelAverage(float f0) { return f0 + (1.0 - f0) / 21.0; }
vec3 fresnelAverage(vec3 f0) { return f0 + (1.0 - f0) / 21.0; }

// Kulla & Conty's Fresnel factor of the multiple-scattering lobe [1]: F_avg² E_avg / (1 - F_avg (1 - E_avg)).
// float32: the denominator as (1 - F_avg) + F_avg E_avg, which does not cancel when both are near 1.
float fresnelMultipleScatteringKullaConty(float fAvg, float eAvg) {
  return fAvg * fAvg * eAvg / max(1.0 - fAvg + fAvg * eAvg, 1e-7);
}
vec3 fresnelMultipleScatteringKullaConty(vec3 fAvg, float eAvg) {
  return fAvg * fAvg * eAvg / max(1.0 - fAvg + fAvg * eAvg, vec3(1e-7));
}

// Turquin's factor on the single-scattering lobe [2]: 1 + f0 (1 - E)/E, E floored at 1e-4.
float energyCompensationTurquin(float f0, float E) {
  float e = clamp(E, 1e-4, 1.0);
  return 1.0 + f0 * (1.0 - e) / e;
}
vec3 energyCompensationTurquin(vec3 f0, float E) {
  float e = clamp(E, 1e-4, 1.0);
  return 1.0 + f0 * (1.0 - e) / e;
}

// Kulla & Conty's lobe from the energy lost [1]: (1 - E_l)(1 - E_v) / (pi (1 - E_avg)). The losses come in
// directly: as alpha -> 0 they are ~1e-7, which float32 holds but 1 - E computed from E near 1 would not.
float multipleScatteringFromLoss(float lossL, float lossV, float lossAvg) {
  if (lossAvg <= 0.0) return 0.0;
  return saturate(lossL) * saturate(lossV) / (PI * min(lossAvg, 1.0));
}

#ifdef ALBEDO_TABLE_GGX
uniform sampler2D uAlbedoTableGGX;

// (1 - E(mu, alpha), 1 - E_avg(alpha), bias), bilinear in (cbrt(mu), cbrt(alpha)) by hand with texelFetch, so
// float textures need no filtering extension and the rule is the JS one exactly. bias: the split sum's.
vec3 albedoLossTableGGX(float mu, float alpha) {
  ivec2 size = textureSize(uAlbedoTableGGX, 0);
  vec2 p = pow(clamp(vec2(mu, alpha), 0.0, 1.0), vec2(1.0 / 3.0)) * vec2(size - 1); // pow(0, 1/3) = 0: y > 0
  ivec2 i = min(ivec2(p), size - 2);
  vec2 f = p - vec2(i);
  vec3 t00 = texelFetch(uAlbedoTableGGX, i, 0).rgb;
  vec3 t10 = texelFetch(uAlbedoTableGGX, i + ivec2(1, 0), 0).rgb;
  vec3 t01 = texelFetch(uAlbedoTableGGX, i + ivec2(0, 1), 0).rgb;
  vec3 t11 = texelFetch(uAlbedoTableGGX, i + ivec2(1, 1), 0).rgb;
  vec3 lo = mix(t00, t10, f.x);
  vec3 hi = mix(t01, t11, f.x);
  return mix(lo, hi, f.y);
}

float averageAlbedoGGX(float alpha) { return 1.0 - albedoLossTableGGX(1.0, alpha).y; }

// Kulla & Conty's lobe for GGX with F = 1 [1], in 1/sr; 0 below the horizon.
float multipleScatteringKullaConty(float nl, float nv, float alpha) {
  if (nl <= 0.0 || nv <= 0.0) return 0.0;
  vec3 v = albedoLossTableGGX(nv, alpha);
  return multipleScatteringFromLoss(albedoLossTableGGX(nl, alpha).x, v.x, v.y);
}

// Directional albedo of GGX with Schlick's F at f0, from the table, with no compensation, Kulla & Conty's
// lobe (its integral is 1 - E, times the Fresnel factor) or Turquin's factor. Mirrors specularAlbedoFromTable.
float specularAlbedoGGX(float mu, float alpha, float f0) {
  vec3 t = albedoLossTableGGX(mu, alpha);
  return f0 * (1.0 - t.x) + (1.0 - f0) * t.z;
}
float specularAlbedoKullaConty(float mu, float alpha, float f0) {
  vec3 t = albedoLossTableGGX(mu, alpha);
  float single = f0 * (1.0 - t.x) + (1.0 - f0) * t.z;
  return single + fresnelMultipleScatteringKullaConty(fresnelAverage(f0), 1.0 - t.y) * t.x;
}
float specularAlbedoTurquin(float mu, float alpha, float f0) {
  vec3 t = albedoLossTableGGX(mu, alpha);
  float single = f0 * (1.0 - t.x) + (1.0 - f0) * t.z;
  return single * energyCompensationTurquin(f0, 1.0 - t.x);
}
#endif
