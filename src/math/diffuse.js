// Diffuse terms, in 1/sr like every BRDF here. 0 at and below the horizon (n·l <= 0 or n·v <= 0),
// except Lambert, which takes no angles (the reflectance equation's n·l clamps it).
import { fresnelSchlick } from './fresnel.js';

const clamp01 = (x) => Math.min(Math.max(x, 0), 1);
const above = (nl, nv) => nl > 0 && nv > 0;

/** Lambert: c_diff / pi, where c_diff is the share of light scattered back (the diffuse colour). */
export function diffuseLambert(cdiff) {
  return clamp01(cdiff) / Math.PI;
}

/**
 * The diffuse-specular trade-off at its simplest: Lambert weighted by the light that Fresnel lets through on
 * the way in and on the way out, (1 - F(n·l)) (1 - F(n·v)) c_diff / pi (reciprocal; 0 at grazing, where the
 * specular term takes everything).
 */
export function diffuseFresnelWeighted(nl, nv, f0, cdiff) {
  if (!above(nl, nv)) return 0;
  return (1 - fresnelSchlick(f0, nl)) * (1 - fresnelSchlick(f0, nv)) * diffuseLambert(cdiff);
}

/**
 * Ashikhmin & Shirley 2000, "An Anisotropic Phong BRDF Model": a diffuse term coupled to the specular
 * one's Fresnel so that together they do not create energy,
 *   28/(23 pi) c_diff (1 - f0) (1 - (1 - n·l/2)^5) (1 - (1 - n·v/2)^5).
 */
export function diffuseAshikhminShirley(nl, nv, f0, cdiff) {
  if (!above(nl, nv)) return 0;
  const p5 = (c) => {
    const m = 1 - Math.min(c, 1) / 2;
    const m2 = m * m;
    return 1 - m2 * m2 * m;
  };
  return (28 / (23 * Math.PI)) * clamp01(cdiff) * (1 - clamp01(f0)) * p5(nl) * p5(nv);
}

/**
 * Oren & Nayar 1994, the full model (with the inter-reflection term L2) for a surface of V-grooves whose
 * slopes have standard deviation sigma (radians); cosPhiDiff = cos of the azimuth between l and v.
 * With alpha = max(theta_l, theta_v), beta = min(...):
 *   C1 = 1 - 0.5 s²/(s² + 0.33),  C2 = 0.45 s²/(s² + 0.09) (sin a, or sin a - (2b/pi)³ when cos phi < 0),
 *   C3 = 0.125 s²/(s² + 0.09) (4ab/pi²)²,
 *   f = c/pi (C1 + cos phi C2 tan b + (1 - |cos phi|) C3 tan((a + b)/2))
 *     + 0.17 c²/pi s²/(s² + 0.13) (1 - cos phi (2b/pi)²).
 * sigma = 0 gives Lambert.
 */
export function diffuseOrenNayar(nl, nv, cosPhiDiff, sigma, cdiff) {
  if (!above(nl, nv)) return 0;
  const s2 = sigma * sigma;
  const c = clamp01(cdiff);
  const cp = Math.min(Math.max(cosPhiDiff, -1), 1);
  // alpha is the angle of the smaller cosine, beta of the larger; the tangents come from the cosines
  // (tan(acos c) at c near 0 is where float32 breaks down), tan((a + b)/2) = (sin a + sin b)/(cos a + cos b)
  const cosA = Math.min(nl, nv, 1);
  const cosB = Math.min(Math.max(nl, nv), 1);
  const sinA = Math.sqrt((1 - cosA) * (1 + cosA));
  const sinB = Math.sqrt((1 - cosB) * (1 + cosB));
  const a = Math.acos(cosA);
  const b = Math.acos(cosB);
  const tanB = sinB / cosB;
  const tanHalfSum = (sinA + sinB) / (cosA + cosB);
  const C1 = 1 - (0.5 * s2) / (s2 + 0.33);
  // with t = 2b/pi, the differences sin a - t³ and 1 - cos phi t² cancel at grazing angles (and are then
  // multiplied by tan b ~ 1/cos b): 1 - t = (2/pi) asin(cos b) and sin a - 1 = -cos²a/(1 + sin a) keep them exact
  const u = (2 / Math.PI) * Math.asin(cosB); // 1 - t
  const t = 1 - u;
  const sinAMinusT3 = -(cosA * cosA) / (1 + sinA) + u * (1 + t + t * t);
  const C2 = ((0.45 * s2) / (s2 + 0.09)) * (cp >= 0 ? sinA : sinAMinusT3);
  const C3 = ((0.125 * s2) / (s2 + 0.09)) * ((4 * a * b) / (Math.PI * Math.PI)) ** 2;
  const L1 = (c / Math.PI) * (C1 + cp * C2 * tanB + (1 - Math.abs(cp)) * C3 * tanHalfSum);
  const L2 = ((0.17 * c * c) / Math.PI) * (s2 / (s2 + 0.13)) * (1 - cp + cp * u * (1 + t));
  return Math.max(L1 + L2, 0);
}

/**
 * The common simplification of Oren-Nayar (their "qualitative model"): c/pi (A + B max(0, cos phi) sin a tan b),
 * A = 1 - 0.5 s²/(s² + 0.33), B = 0.45 s²/(s² + 0.09). sin a tan b is formed from the cosines directly:
 * sin a = sqrt(1 - min(nl, nv)²), tan b = sqrt(1 - max(nl, nv)²)/max(nl, nv).
 */
export function diffuseOrenNayarQualitative(nl, nv, cosPhiDiff, sigma, cdiff) {
  if (!above(nl, nv)) return 0;
  const s2 = sigma * sigma;
  const lo = Math.min(nl, nv, 1);
  const hi = Math.min(Math.max(nl, nv), 1);
  const sinA = Math.sqrt((1 - lo) * (1 + lo));
  const tanB = Math.sqrt((1 - hi) * (1 + hi)) / hi;
  const A = 1 - (0.5 * s2) / (s2 + 0.33);
  const B = (0.45 * s2) / (s2 + 0.09);
  return (clamp01(cdiff) / Math.PI) * (A + B * Math.max(cosPhiDiff, 0) * sinA * tanB);
}
