// surfaces' model, as pure functions: what a flat interface does with light (exact Fresnel, Snell, the depth a
// metal absorbs within), and where a rough surface reflects it, ray traced and as the microfacet model predicts.
import { fresnelParams, isMetal, materialByKey } from '../../math/materials.js';
import { fresnelConductor, fresnelDielectric } from '../../math/fresnel.js';
import { measuredRgbNk } from '../../math/optical-constants.js';
import { generateProfile, reflectedAngleDensity, reflectedAngles, seededRandom } from '../../math/microsurface.js';
import { smithG1Beckmann } from '../../math/visibility.js';
import { DEG, TO_DEGREES } from '../../math/angles.js';

const PROFILE = 60000;
const RAYS = 30000;
const CONE_BINS = 90; // outgoing angles -90°..90°

/** The flat interface for the picture: { theta (deg), F, etaRefr (real index for Snell), metal, depthNm, name }. */
export function interfaceSpec(s) {
  const p = fresnelParams(s.material);
  const c = Math.cos(s.theta * DEG);
  const metal = isMetal(s.material);
  const green = 1; // the 550 nm channel stands for the picture
  const F = metal ? fresnelConductor(c, p.eta[green], p.k[green]) : fresnelDielectric(c, p.eta[green]);
  const k550 = metal ? measuredRgbNk(s.material)[green][1] : 0;
  return {
    theta: s.theta,
    F,
    etaRefr: metal ? Math.max(p.eta[green], 1) : p.eta[green],
    metal,
    depthNm: metal ? 550 / (4 * Math.PI * k550) : 0,
    name: materialByKey(s.material).name,
  };
}

/** A rough surface's height profile (Beckmann slopes of roughness alpha), the same for the same alpha. */
export const roughProfile = (alpha) => generateProfile(PROFILE, 'beckmann', alpha, 2);

/**
 * Where light from s.theta goes after one reflection off `profile`: the share per degree of outgoing angle,
 * ray traced (`counts`) and as the microfacet model predicts (`predicted`), at bin centres `xs` (degrees).
 */
export function reflectionCone(s, profile) {
  const ti = s.theta * DEG;
  const width = Math.PI / CONE_BINS;
  const counts = new Float64Array(CONE_BINS);
  for (const t of reflectedAngles(profile, ti, RAYS, seededRandom(11))) {
    const b = Math.floor((t + Math.PI / 2) / width);
    if (b >= 0 && b < CONE_BINS) counts[b] += 1 / RAYS / width / TO_DEGREES;
  }
  const xs = Float64Array.from({ length: CONE_BINS }, (_, b) => ((b + 0.5) * width - Math.PI / 2) / DEG);
  const predicted = xs.map(
    (deg) => reflectedAngleDensity(deg * DEG, ti, 'beckmann', s.alpha, smithG1Beckmann) / TO_DEGREES,
  );
  return { xs, counts, predicted };
}
