// OpenPBR Surface's base diffuse lobe: EON, the "energy-preserving Oren–Nayar" of Portsmouth, d'Eon et al.
// (2024, "EON: A practical energy-preserving rough diffuse BRDF"), which the specification (v1.1.1, "Glossy-diffuse")
// and MaterialX 1.39's oren_nayar_diffuse_bsdf (energy_compensation = true) use: Fujii's 2012 form of Oren–Nayar
// (the "improved Oren–Nayar") plus a reciprocal lobe that returns what its single scattering loses. Roughness
// r = base_diffuse_roughness in [0, 1] (not the radians σ of diffuse.js's Oren–Nayar 1994). In 1/sr, 0 below the
// horizon; (nl, nv, lv) are n·l, n·v and l·v.

const INV_PI = 1 / Math.PI;
/** Fujii's constants: A = 1 / (1 + C1 r), and the average albedo A (1 + C2 r). */
const C1 = 0.5 - 2 / (3 * Math.PI);
const C2 = 2 / 3 - 28 / (15 * Math.PI);
const clamp01 = (x) => Math.min(Math.max(x, 0), 1);

/**
 * G(μ)/π of the exact directional albedo of Fujii's Oren–Nayar, E(μ) = A (1 + r G(μ)/π) (Portsmouth et al. 2024,
 * eq. 8): G = sinθ (θ − sinθ cosθ) + (2/3)(sinθ/cosθ)(1 − sin³θ) − (2/3) sinθ, with 1 − sin³θ written as
 * cos²θ (1 + s + s²)/(1 + s) so that the grazing end has no 0/0. G/π runs from 0 (μ = 1) to C1 (μ = 0).
 */
function fujiiAlbedoG(mu) {
  const c = clamp01(mu);
  const s = Math.sqrt((1 - c) * (1 + c));
  const theta = Math.acos(c);
  const g = s * (theta - s * c) + ((2 / 3) * s * c * (1 + s + s * s)) / (1 + s) - (2 / 3) * s;
  return g * INV_PI;
}

/** Directional albedo of Fujii's Oren–Nayar with ρ = 1: A (1 + r G(μ)/π), exact. */
export function albedoFujiiOrenNayar(mu, roughness) {
  const r = clamp01(roughness);
  return (1 + r * fujiiAlbedoG(mu)) / (1 + C1 * r);
}

/** Its cosine-weighted average 2∫E μ dμ = A (1 + C2 r), exact. */
export function averageAlbedoFujiiOrenNayar(roughness) {
  const r = clamp01(roughness);
  return (1 + C2 * r) / (1 + C1 * r);
}

/**
 * Fujii's Oren–Nayar with ρ = 1: A (1 + r s/t)/π, s = l·v − (n·l)(n·v), t = max(n·l, n·v) where s > 0, else 1.
 */
export function diffuseFujiiOrenNayar(nl, nv, lv, roughness) {
  if (!(nl > 0 && nv > 0)) return 0;
  const r = clamp01(roughness);
  const s = lv - nl * nv;
  const sOverT = s > 0 ? s / Math.max(nl, nv) : s;
  return (INV_PI * (1 + r * sOverT)) / (1 + C1 * r);
}

/**
 * EON for albedo ρ (one channel, ρ in [0, 1]): Fujii's lobe ρ f_FON plus
 *   f_ms = ρ_ms (1 − E(n·l))(1 − E(n·v)) / (π (1 − E_avg)),  ρ_ms = ρ² E_avg / (1 − ρ (1 − E_avg)),
 * with 1 − E(μ) = A r (C1 − G(μ)/π) and 1 − E_avg = A r (C1 − C2), so r = 0 (Lambert) has no 0/0. With ρ = 1
 * its albedo is 1 at every angle (the white furnace, tested). The specification prints ρ_ms with one more 1/π and
 * E_avg/(1 − E_avg) in place of E_avg, which would not pass that furnace; this is the paper's and MaterialX's form.
 */
export function diffuseEON(nl, nv, lv, roughness, rho) {
  if (!(nl > 0 && nv > 0)) return 0;
  const r = clamp01(roughness);
  const p = clamp01(rho);
  const a = 1 / (1 + C1 * r);
  const avg = a * (1 + C2 * r);
  const rhoMs = (p * p * avg) / (1 - p * (1 - avg));
  const ms = (rhoMs * a * r * (C1 - fujiiAlbedoG(nl)) * (C1 - fujiiAlbedoG(nv))) / (Math.PI * (C1 - C2));
  return p * diffuseFujiiOrenNayar(nl, nv, lv, r) + ms;
}
