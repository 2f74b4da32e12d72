// OpenPBR Surface (Academy Software Foundation, specification v1.1.1) as one BRDF, openPbrBRDF(l, v, material) →
// [r, g, b] in 1/sr (no cosine), l and v unit vectors in the local frame (n = z, the tangent = x). The subset with
// the base (metal, dielectric gloss over the EON diffuse lobe), the coat and the fuzz: no transmission, subsurface,
// thin film, emission, opacity or thin-walled mode, and one normal and tangent for every layer.
//
// material: an object with the specification's own parameter names, each optional (missing keys take the
// specification's defaults, OPENPBR_DEFAULTS; a colour is [r, g, b] or one number for grey; values are clamped to
// the specification's ranges, and specular_ior and coat_ior below 1 are taken as 1, since the reflection
// from a medium of lower index needs the transmission this subset leaves out); an unknown key throws, naming it:
//   base_weight 1, base_color [0.8, 0.8, 0.8], base_metalness 0, base_diffuse_roughness 0,
//   specular_weight 1, specular_color [1, 1, 1], specular_roughness 0.3, specular_roughness_anisotropy 0,
//   specular_ior 1.5, coat_weight 0, coat_color [1, 1, 1], coat_roughness 0, coat_roughness_anisotropy 0,
//   coat_ior 1.6, coat_darkening 1, fuzz_weight 0, fuzz_color [1, 1, 1], fuzz_roughness 0.5.
//
// The composition: the specification's "Model", reduced to a sum of lobes by the albedo scaling it describes (where
// its MaterialX reference graph open_pbr_surface differs, docs/openpbr.md says how), E the directional albedo at v:
//   dielectric = specular_color·F_d D V/4 + (1 − E_d(n·v)) base_weight·EON(base_color, base_diffuse_roughness)
//   metal      = specular_weight·F82-tint(base_weight·base_color, specular_color) D V/4
//   base       = lerp(dielectric, metal, base_metalness) · lerp(1, Δ, coat_weight·coat_darkening)
//   coated     = coat_weight·f_coat + lerp(1, T(l, v)(1 − E_c(n·v)), coat_weight) · base
//   surface    = fuzz_weight·fuzz_color·f_fuzz + (1 − fuzz_weight·R(n·v)) · coated
// GGX with height-correlated Smith, α = roughness² and the specification's anisotropy mapping; the base's roughness
// widened by the coat's (its "Roughening"); F_d the exact dielectric Fresnel at the specification's modulated
// index (specular_weight scales F0; specular_ior over coat_ior where coated, inverted above 1 against total
// internal reflection); Δ the coat's darkening (1 − K)/(1 − E_b K) with the specification's recommended K and the
// reference graph's E_b;
// T = coat_color^((1/μt_l + 1/μt_v)/2), the specification's view-dependent absorption along the refracted paths.
// Single scattering in every microfacet lobe (the talk's model); see docs/openpbr.md for what that loses.
import { fresnelDielectric, fresnelF82Tint } from './fresnel.js';
import { anisotropicAlphas, ndfGGXAniso, visibilitySmithGGXCorrelatedAniso } from './anisotropic.js';
import { diffuseEON } from './openpbr-diffuse.js';
import { albedoFuzzZeltner, fuzzZeltner } from './openpbr-fuzz.js';
import { fresnelDielectricAverage, openPbrDielectricAlbedo } from './openpbr-albedo.js';

const GREY = (x) => Object.freeze([x, x, x]);
/** The specification's defaults (v1.1.1, "Parameter reference") for the keys of the subset. */
export const OPENPBR_DEFAULTS = Object.freeze({
  base_weight: 1,
  base_color: GREY(0.8),
  base_metalness: 0,
  base_diffuse_roughness: 0,
  specular_weight: 1,
  specular_color: GREY(1),
  specular_roughness: 0.3,
  specular_roughness_anisotropy: 0,
  specular_ior: 1.5,
  coat_weight: 0,
  coat_color: GREY(1),
  coat_roughness: 0,
  coat_roughness_anisotropy: 0,
  coat_ior: 1.6,
  coat_darkening: 1,
  fuzz_weight: 0,
  fuzz_color: GREY(1),
  fuzz_roughness: 0.5,
});

/** Upper bounds beyond [0, 1]: the indices are unbounded, specular_weight up to 1/F0 (clamped where it is used). */
const UPPER = { specular_ior: Infinity, coat_ior: Infinity, specular_weight: Infinity };
const LOWER = { specular_ior: 1, coat_ior: 1 };

/** One value, clamped to its range; a non-finite one is refused. */
function clampParam(key, x) {
  if (typeof x !== 'number' || !Number.isFinite(x)) throw new Error(`openPbrMaterial: ${key} is not a finite number`);
  return Math.min(Math.max(x, LOWER[key] ?? 0), UPPER[key] ?? 1);
}

const FILLED = new WeakSet(); // materials openPbrMaterial made: passed through as they are

/**
 * The material with every key of the subset: defaults filled in, values clamped, colours as [r, g, b]; frozen.
 * Passing its result again costs nothing (a renderer or a quadrature fills a material once).
 */
export function openPbrMaterial(material = {}) {
  if (FILLED.has(material)) return material;
  const unknown = Object.keys(material).filter((k) => !(k in OPENPBR_DEFAULTS));
  if (unknown.length) throw new Error(`openPbrMaterial: unknown parameter ${unknown.join(', ')}`);
  const out = {};
  for (const [key, fallback] of Object.entries(OPENPBR_DEFAULTS)) {
    const value = material[key] ?? fallback;
    if (Array.isArray(fallback)) {
      const rgb = typeof value === 'number' ? [value, value, value] : value;
      if (!Array.isArray(rgb) || rgb.length !== 3) throw new Error(`openPbrMaterial: ${key} is not [r, g, b]`);
      out[key] = Object.freeze(rgb.map((c) => clampParam(key, c)));
    } else out[key] = clampParam(key, value);
  }
  FILLED.add(Object.freeze(out));
  return out;
}

const lerp = (a, b, t) => a + (b - a) * t;
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** D V / 4 of anisotropic GGX with height-correlated Smith at the half vector h, the pair [αt, αb]. */
function ggxLobe(l, v, h, alphas) {
  const d = ndfGGXAniso(h[0], h[1], h[2], alphas[0], alphas[1]);
  return (d * visibilitySmithGGXCorrelatedAniso(...l, ...v, alphas[0], alphas[1])) / 4;
}

/** The specification's ηs before specular_weight: specular_ior over the coat's where coated, inverted below 1. */
function openPbrUnmodulatedEta(m) {
  const coated = m.specular_ior / m.coat_ior;
  return lerp(m.specular_ior, coated > 1 ? coated : 1 / coated, m.coat_weight);
}

/** The specification's ηs, modulated by specular_weight (F0 scaled by it, eq. "modulated_ior"). */
export function openPbrSpecularEta(m) {
  const eta = openPbrUnmodulatedEta(m);
  const f0 = ((eta - 1) / (eta + 1)) ** 2;
  const eps = Math.sign(eta - 1) * Math.sqrt(Math.min(Math.max(m.specular_weight * f0, 0), 0.99999));
  return (1 + eps) / (1 - eps);
}

/** The base's roughness widened by the coat's: lerp(r, min(1, r⁴ + 2 r_c⁴)^(1/4), coat_weight). */
export const openPbrBaseRoughness = (m) =>
  lerp(m.specular_roughness, Math.min(1, m.specular_roughness ** 4 + 2 * m.coat_roughness ** 4) ** 0.25, m.coat_weight);

/**
 * The coat's darkening of the base, lerp(1, Δ, coat_weight·coat_darkening) per channel, Δ = (1 − K)/(1 − E_b K)
 * (the specification's "Darkening"), at n·v = nv. K, the share of the light leaving the base that the coat sends
 * back: the specification's recommendation lerp(K_s, K_r, r_b), K_s = F(n·v, η_c) for a smooth base,
 * K_r = 1 − (1 − F̄(η_c))/η_c² for a Lambertian one, r_b = lerp(lerp(1, r, ξ F_s), r, M) the base's roughness. With
 * `referenceGraph`, the simpler K = 1 − (1 − F0(η_c))/η_c² of its MaterialX graph (for every base; the tests
 * measure both against the random walk). E_b = lerp(base_color, specular_weight·base_color, M), as the graph has it.
 */
export function openPbrCoatDarkening(m, nv, referenceGraph = false) {
  const eta = m.coat_ior;
  const f0 = ((eta - 1) / (eta + 1)) ** 2;
  let k = 1 - (1 - f0) / (eta * eta);
  if (!referenceGraph) {
    const etaS = openPbrUnmodulatedEta(m);
    const fs = Math.min(Math.max(m.specular_weight * ((etaS - 1) / (etaS + 1)) ** 2, 0), 1);
    const r = m.specular_roughness;
    const rb = lerp(lerp(1, r, fs), r, m.base_metalness);
    k = lerp(fresnelDielectric(nv, eta), 1 - (1 - fresnelDielectricAverage(eta)) / (eta * eta), rb);
  }
  return m.base_color.map((c) => {
    const eb = lerp(c, c * m.specular_weight, m.base_metalness);
    return lerp(1, (1 - k) / (1 - eb * k), m.coat_weight * m.coat_darkening);
  });
}

/** cos θ inside the coat of a ray at cos θ outside: sqrt(1 − (1 − μ²)/η²). */
const refractedCos = (mu, eta) => Math.sqrt(Math.max(1 - (1 - mu * mu) / (eta * eta), 0));

/**
 * Each layer's part of the BRDF at (l, v), [r, g, b] in 1/sr, already weighted so that they sum to openPbrBRDF:
 * { specular, diffuse, metal, coat, fuzz } (specular and diffuse: the dielectric base's gloss and diffuse lobe).
 */
export function openPbrLayers(l, v, material) {
  const m = openPbrMaterial(material);
  const zero = [0, 0, 0];
  if (!(l[2] > 0 && v[2] > 0)) return { specular: zero, diffuse: zero, metal: zero, coat: zero, fuzz: zero };
  const hl = Math.hypot(l[0] + v[0], l[1] + v[1], l[2] + v[2]);
  const h = [(l[0] + v[0]) / hl, (l[1] + v[1]) / hl, (l[2] + v[2]) / hl];
  const lh = dot(l, h);
  const nv = v[2];
  const rBase = openPbrBaseRoughness(m);
  const lobe = ggxLobe(l, v, h, anisotropicAlphas(rBase * rBase, m.specular_roughness_anisotropy, 'openpbr'));
  const eta = openPbrSpecularEta(m);
  const fd = fresnelDielectric(lh, eta) * lobe;
  const gloss = 1 - openPbrDielectricAlbedo(nv, rBase * rBase, eta);
  const lv = dot(l, v);
  const metalF0 = m.base_color.map((c) => m.base_weight * c);
  // the coat's factor on everything beneath it, and the fuzz's on everything beneath it
  const cAlpha = m.coat_roughness * m.coat_roughness;
  const coatAlbedo = openPbrDielectricAlbedo(nv, cAlpha, m.coat_ior);
  const path = 0.5 * (1 / refractedCos(l[2], m.coat_ior) + 1 / refractedCos(nv, m.coat_ior));
  const darkening = openPbrCoatDarkening(m, nv);
  const fuzzAlbedo = albedoFuzzZeltner(nv, m.fuzz_roughness);
  const above = 1 - m.fuzz_weight * fuzzAlbedo;
  const below = m.coat_color.map((t, c) => above * lerp(1, t ** path * (1 - coatAlbedo), m.coat_weight) * darkening[c]);
  const dielectric = 1 - m.base_metalness;
  const coatLobe = ggxLobe(l, v, h, anisotropicAlphas(cAlpha, m.coat_roughness_anisotropy, 'openpbr'));
  const coat = m.coat_weight * fresnelDielectric(lh, m.coat_ior) * coatLobe * above;
  const fuzz = m.fuzz_weight * fuzzZeltner(l, v, m.fuzz_roughness);
  return {
    specular: m.specular_color.map((t, c) => below[c] * dielectric * t * fd),
    diffuse: m.base_color.map((rho, c) => {
      const f = diffuseEON(l[2], nv, lv, m.base_diffuse_roughness, rho);
      return below[c] * dielectric * gloss * m.base_weight * f;
    }),
    metal: metalF0.map(
      (f0, c) => below[c] * m.base_metalness * m.specular_weight * fresnelF82Tint(f0, m.specular_color[c], lh) * lobe,
    ),
    coat: [coat, coat, coat],
    fuzz: m.fuzz_color.map((t) => t * fuzz),
  };
}

/** OpenPBR Surface's BRDF (the subset above) at (l, v), [r, g, b] in 1/sr: the sum of openPbrLayers. */
export function openPbrBRDF(l, v, material = {}) {
  const p = openPbrLayers(l, v, material);
  return [0, 1, 2].map((c) => p.specular[c] + p.diffuse[c] + p.metal[c] + p.coat[c] + p.fuzz[c]);
}
