// The directional albedo of the lab's specular lobe, for the methods that light it with uniform radiance (the split
// sum, ambient light): the DFG table of the chosen D and V (uDfg, made for them) and the compensation's share.
#include "integrate.glsl"

uniform sampler2D uDfg;

// The DFG table at (n·v, alpha) (dfgTableUv): (A, B) with ∫ f (n·l) dω = F0·A + B for Schlick's F, and A + B for
// F = 1 (the two parts of the split add back up to the albedo).
vec3 dfgAlbedo(float nv) {
  vec2 ab = texture(uDfg, dfgTableUv(nv, uAlpha)).rg;
#ifdef F_ONE
  vec3 single = vec3(ab.x + ab.y);
#else
  vec3 single = uF0 * ab.x + ab.y;
#endif
#ifdef COMPENSATION_TURQUIN
  single *= energyCompensationTurquin(F0_BOUNCES, 1.0 - albedoLossTableGGX(nv, uAlpha).x);
#endif
  return single;
}

// What Kulla & Conty's lobe adds under uniform light of radiance 1: F_ms (1 - E(n·v)) (its integral); under an
// environment it is applied to the irradiance, as the lobe is nearly flat in l (Fdez-Agüera 2019).
vec3 multipleAlbedo(float nv) {
#ifdef COMPENSATION_KULLA_CONTY
  return fresnelBounces() * albedoLossTableGGX(nv, uAlpha).x;
#else
  return vec3(0.0);
#endif
}
