// The energy a single-scattering microfacet BRDF loses, put back. The microfacet model counts only light that
// leaves after one reflection; what a facet sends into its neighbours is dropped, so with F = 1 the albedo
// E(mu) = ∫ f (n·l) dω falls below 1 (to 1 - ln 2 ≈ 0.31 for GGX at alpha = 1 and normal incidence).
// Two published fixes, both built on E (GGX, height-correlated Smith, F = 1: albedoGGX of integrate.js):
//   [1] Kulla & Conty, "Revisiting Physically Based Shading at Imageworks", SIGGRAPH 2017 course notes:
//       an extra lobe f_ms = (1 - E(mu_l))(1 - E(mu_v)) / (pi (1 - E_avg)), times a Fresnel factor.
//   [2] Turquin, "Practical multiple scattering compensation for microfacet models", tech. report 2019:
//       scale the single-scattering lobe by 1 + F0 (1 - E(mu_v)) / E(mu_v).
// Both approximate the random walk on the Smith microsurface (random-walk.js) of
//   [3] Heitz, Hanika, d'Eon & Jakob, "Multiple-scattering microfacet BSDFs with the Smith model", SIGGRAPH 2016.
import { albedoGGX, averageAlbedo, dfgSplitSum } from './integrate.js';

const clamp01 = (x) => Math.min(Math.max(x, 0), 1);

let lastAverage = { alpha: NaN, value: NaN }; // lobes evaluate many (l, v) at one alpha

/**
 * E_avg(alpha) = 2 ∫ E(mu) mu dmu for GGX, height-correlated Smith, F = 1 [1], by averageAlbedo (16-node
 * Gauss–Legendre in sqrt(mu)). Its error is at most albedoGGX's (the weights are positive and sum to 1) plus
 * the rule's (below 1e-7, see the tests).
 */
export function averageAlbedoGGX(alpha) {
  if (alpha !== lastAverage.alpha) lastAverage = { alpha, value: averageAlbedo((mu) => albedoGGX(mu, alpha)) };
  return lastAverage.value;
}

/**
 * Kulla & Conty's lobe [1] from the energy lost, 1 - E: (1 - E_l)(1 - E_v) / (pi (1 - E_avg)). Its integral
 * ∫ f_ms (n·l) dω = 1 - E_v is what the single-scattering lobe lost (the white furnace is closed). Taking the
 * losses rather than E keeps their digits in float32 as alpha → 0, where all three go to 0 together.
 */
export function multipleScatteringFromLoss(lossL, lossV, lossAvg) {
  if (!(lossAvg > 0)) return 0;
  return (clamp01(lossL) * clamp01(lossV)) / (Math.PI * Math.min(lossAvg, 1));
}

/** Kulla & Conty's multiple-scattering lobe [1] for GGX with F = 1, in 1/sr; 0 below the horizon. */
export function multipleScatteringKullaConty(nl, nv, alpha) {
  if (!(nl > 0 && nv > 0)) return 0;
  const loss = (mu) => 1 - albedoGGX(Math.min(mu, 1), alpha);
  return multipleScatteringFromLoss(loss(nl), loss(nv), 1 - averageAlbedoGGX(alpha));
}

/** The cosine-weighted average of Schlick's Fresnel, 2 ∫ F(mu) mu dmu = f0 + (1 - f0)/21 (a Beta integral). */
export function fresnelAverage(f0) {
  return f0 + (1 - f0) / 21;
}

/**
 * Kulla & Conty's Fresnel factor for the multiple-scattering lobe [1]: F_avg² E_avg / (1 - F_avg (1 - E_avg)),
 * the sum over k ≥ 0 of F_avg^(k+2) E_avg (1 - E_avg)^k: light that bounces k + 2 times, meeting an average
 * Fresnel at each, leaving with probability E_avg. 1 when F_avg = 1. Domain: F_avg in [0, 1], E_avg in (0, 1].
 */
export function fresnelMultipleScatteringKullaConty(fAvg, eAvg) {
  // 1 - F_avg (1 - E_avg) written as (1 - F_avg) + F_avg E_avg: no cancellation when both are near 1
  return (fAvg * fAvg * eAvg) / Math.max(1 - fAvg + fAvg * eAvg, 1e-7);
}

/**
 * Turquin's energy compensation [2]: the factor 1 + f0 (1 - E)/E that scales the single-scattering lobe,
 * E = E(mu_v) with F = 1. With f0 = 1 the compensated albedo E · factor is exactly 1. E is floored at 1e-4.
 */
export function energyCompensationTurquin(f0, E) {
  const e = Math.min(Math.max(E, 1e-4), 1);
  return 1 + (f0 * (1 - e)) / e;
}

/**
 * Directional albedo ∫ f (n·l) dω of GGX with Schlick's Fresnel at f0 (one channel), with a compensation:
 * single scattering is F0·scale + bias of the split sum; Kulla–Conty adds its lobe's integral 1 - E(mu)
 * times the Fresnel factor; Turquin scales single scattering by its factor.
 */
export function compensatedAlbedoGGX(mu, alpha, f0, compensation, Eavg = averageAlbedoGGX(alpha)) {
  const [scale, bias] = dfgSplitSum(mu, alpha);
  const single = f0 * scale + bias;
  const E = scale + bias;
  const factor = fresnelMultipleScatteringKullaConty(fresnelAverage(f0), Eavg);
  if (compensation === 'kullaConty') return single + factor * (1 - E);
  if (compensation === 'turquin') return single * energyCompensationTurquin(f0, E);
  return single;
}
