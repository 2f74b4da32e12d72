// The truth OpenPBR's albedo scaling is measured against: light followed through the layers themselves, a coat
// (a rough dielectric interface over an absorbing medium of unit thickness) over a base (Lambert, or a GGX metal
// with F82-tint), by Monte Carlo. Position-free (Guo, Hašan & Zhao 2018, "Position-free Monte Carlo simulation for
// arbitrary layered BSDFs"): the layers are infinite and uniform, so a path needs its direction and its layer, not
// where it is. For a directional albedo the forward walk alone is unbiased (their paper adds next-event estimation
// for BSDF values). Each interface is the single-scattering microfacet model the app's lobes use (GGX, normals
// drawn from those visible, Dupuy & Benyoub 2023): reflection weighted by height-correlated Smith G2/G1, as the
// lobes are, transmission by G1 of the refracted direction (Walter et al. 2007's separable form).
import { fresnelDielectric, fresnelF82Tint } from './fresnel.js';
import { sampleVisibleNormalGGX } from './random-walk.js';
import { sampleCosine } from './integrate.js';
import { seededRandom } from './microsurface.js';

export const LAYERED_WALK_MAX_BOUNCES = 256;

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const flip = (w) => [w[0], w[1], -w[2]];
/** Smith's Λ of GGX for a direction on the normal's side. */
const lambda = (w, alpha) => (Math.sqrt(1 + (alpha * alpha * (w[0] * w[0] + w[1] * w[1])) / (w[2] * w[2])) - 1) / 2;

/**
 * One event at a rough dielectric interface, wi on the side the light comes from (wi.z > 0, pointing away), eta
 * the index beyond over the index before: { wo, weight } (wo.z > 0 reflected, < 0 transmitted), or null when the
 * microsurface shadows the way out (the energy single scattering loses).
 */
function dielectricEvent(wi, alpha, eta, rand) {
  const m = sampleVisibleNormalGGX(wi, alpha, rand(), rand());
  const c = dot(wi, m);
  if (rand() < fresnelDielectric(c, eta)) {
    const wo = m.map((x, i) => 2 * c * x - wi[i]);
    if (!(wo[2] > 0)) return null;
    const li = lambda(wi, alpha);
    return { wo, weight: (1 + li) / (1 + li + lambda(wo, alpha)) };
  }
  const ct = Math.sqrt(Math.max(1 - (1 - c * c) / (eta * eta), 0));
  const wo = m.map((x, i) => (c / eta - ct) * x - wi[i] / eta);
  if (!(wo[2] < 0)) return null;
  return { wo, weight: 1 / (1 + lambda(flip(wo), alpha)) };
}

/** The base's event for a ray arriving from wi (z > 0): { wo, weight: [r, g, b] } or null. */
function baseEvent(base, wi, rand) {
  if (base.kind === 'lambert') return { wo: sampleCosine(rand(), rand()), weight: base.albedo };
  const m = sampleVisibleNormalGGX(wi, base.alpha, rand(), rand());
  const c = dot(wi, m);
  const wo = m.map((x, i) => 2 * c * x - wi[i]);
  if (!(wo[2] > 0)) return null;
  const li = lambda(wi, base.alpha);
  const g = (1 + li) / (1 + li + lambda(wo, base.alpha));
  return { wo, weight: base.f0.map((f0, k) => g * fresnelF82Tint(f0, base.tint[k], c)) };
}

/** One path from direction v; the light it carries out, [r, g, b] (0 when it is lost or dropped). */
function walkPath(v, { coat, base }, rand) {
  let w = [1, 1, 1];
  let d = v; // towards where the light came from, as the base sees it (d.z > 0)
  if (coat) {
    const top = dielectricEvent(v, coat.alpha, coat.eta, rand);
    if (!top) return [0, 0, 0];
    if (top.wo[2] > 0) return [top.weight, top.weight, top.weight];
    w = w.map((x) => x * top.weight);
    d = top.wo.map((x) => -x);
  }
  for (let bounce = 0; bounce < LAYERED_WALK_MAX_BOUNCES; bounce++) {
    const down = coat ? coat.sigma.map((s) => Math.exp(-s / d[2])) : [1, 1, 1];
    const hit = baseEvent(base, d, rand);
    if (!hit) return [0, 0, 0];
    const up = coat ? coat.sigma.map((s) => Math.exp(-s / hit.wo[2])) : [1, 1, 1];
    w = w.map((x, k) => x * down[k] * hit.weight[k] * up[k]);
    if (!coat) return w;
    // at the coat from inside, in the frame whose normal points down into the coat (z flipped)
    const out = dielectricEvent(
      flip(hit.wo).map((x) => -x),
      coat.alpha,
      1 / coat.eta,
      rand,
    );
    if (!out) return [0, 0, 0];
    w = w.map((x) => x * out.weight);
    if (out.wo[2] < 0) return w; // through the top
    d = flip(out.wo).map((x) => -x); // reflected back down
  }
  return [0, 0, 0];
}

/**
 * The directional albedo of a coated base from the direction at cos θ = mu, by `samples` seeded paths:
 * { albedo, standardError } per channel. stack = { coat: { alpha, eta, sigma: [r, g, b] } | null,
 * base: { kind: 'lambert', albedo: [r, g, b] } | { kind: 'conductor', alpha, f0: [r, g, b], tint: [r, g, b] } };
 * the coat's absorption σ per unit thickness (a normal-incidence round trip transmits exp(−2σ)).
 */
export function layeredWalkAlbedo(mu, stack, samples, seed = 1) {
  const rand = seededRandom(seed);
  const v = [Math.sqrt((1 - mu) * (1 + mu)), 0, mu];
  const sum = [0, 0, 0];
  const sum2 = [0, 0, 0];
  for (let i = 0; i < samples; i++) {
    const x = walkPath(v, stack, rand);
    for (let k = 0; k < 3; k++) {
      sum[k] += x[k];
      sum2[k] += x[k] * x[k];
    }
  }
  const albedo = sum.map((s) => s / samples);
  const standardError = sum2.map((s, k) => Math.sqrt(Math.max(s / samples - albedo[k] ** 2, 0) / (samples - 1)));
  return { albedo, standardError };
}
