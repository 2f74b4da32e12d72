// OpenPBR Surface's base (no coat, no fuzz, no transmission, subsurface or thin film) composed from the catalogue's
// own terms, for the MaterialX comparison (tests/browser/materialx.test.js) until src/math/openpbr.js's
// openPbrBRDF stands in for it. The talk's microfacet model, f = F D V / 4 with GGX, height-correlated Smith and
// α = specular_roughness², plus the two things OpenPBR's reference graph (MaterialX's open_pbr_surface.mtlx) adds
// on top, each switchable so that its size can be measured:
// - `turquin`: the multiple-scattering compensation of Turquin 2019, the lobe scaled by 1 + F (1 - E)/E with E the
//   lobe's albedo for F = 1 at n·v. MaterialX takes F at v·h (the lobe's own Fresnel), not at f0 as Turquin does;
//   so does this (`turquinF: 'vh'`), or F0 (`turquinF: 'f0'`).
// - the diffuse under the dielectric specular, scaled by what that specular leaves, 1 - E_spec(n·v): albedo
//   scaling, as OpenPBR specifies the layering. E_spec is Schlick's split sum at f0 = F0(specular_ior) times the
//   compensation, as MaterialX writes it; here its scale and bias are the accurate float64 quadrature
//   (dfgSplitSum), where MaterialX has a rational fit.
// Lambert diffuse: base_diffuse_roughness = 0 in every material compared (MaterialX's energy-preserving
// Oren-Nayar is Lambert there, to 1e-8).
import { dfgSplitSum } from '../../src/math/integrate.js';
import { fresnelDielectric, fresnelF82Tint } from '../../src/math/fresnel.js';
import { ndfGGX } from '../../src/math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';
import { energyCompensationTurquin } from '../../src/math/multiple-scattering.js';
import { brdfAngles } from '../../src/math/brdf.js';

/** OpenPBR Surface 1.1's defaults for the inputs the base reads. */
export const OPENPBR_BASE_DEFAULTS = Object.freeze({
  base_weight: 1,
  base_color: [0.8, 0.8, 0.8],
  base_metalness: 0,
  specular_weight: 1,
  specular_color: [1, 1, 1],
  specular_roughness: 0.3,
  specular_ior: 1.5,
});

const splitSums = new Map();
/** [scale, bias] of the split sum at (μ, α), cached: the comparison asks for the same few hundred many times. */
function splitSum(mu, alpha) {
  const key = `${mu},${alpha}`;
  if (!splitSums.has(key)) splitSums.set(key, dfgSplitSum(mu, alpha));
  return splitSums.get(key);
}

/**
 * OpenPBR's specular_weight on a dielectric: F0 scaled by the weight, and the IOR that has that F0 (the
 * specification's "modulated" IOR, the sign of η - 1 kept).
 */
function modulatedIor(ior, weight) {
  const r = Math.sqrt(Math.min(weight * ((ior - 1) / (ior + 1)) ** 2, 0.99999));
  const s = Math.sign(ior - 1) * r;
  return (1 + s) / (1 - s);
}

/**
 * f(l, v) of the base in 1/sr, [r, g, b], l and v in the local frame (n = z). `options`: { turquin = true,
 * turquinF = 'vh', albedo }: `albedo(μ, α)` → [scale, bias] stands in for the float64 split sum.
 */
export function openPbrBaseBRDF(l, v, material, { turquin = true, turquinF = 'vh', albedo = splitSum } = {}) {
  const m = { ...OPENPBR_BASE_DEFAULTS, ...material };
  const a = brdfAngles(l, v);
  if (!(a.nl > 0 && a.nv > 0) || !a.h) return [0, 0, 0];
  const alpha = m.specular_roughness ** 2;
  const lobe = (ndfGGX(a.nh, alpha) * visibilitySmithGGXCorrelated(a.nl, a.nv, alpha)) / 4;
  const [scale, bias] = albedo(a.nv, alpha);
  const E = scale + bias;
  const comp = (F, f0) => (turquin ? energyCompensationTurquin(turquinF === 'vh' ? F : f0, E) : 1);
  const eta = modulatedIor(m.specular_ior, m.specular_weight);
  const f0d = ((eta - 1) / (eta + 1)) ** 2;
  const Fd = fresnelDielectric(a.lh, eta);
  const dielectricSpecular = lobe * Fd * comp(Fd, f0d);
  const left = 1 - (f0d * scale + bias) * comp(Fd, f0d);
  return [0, 1, 2].map((c) => {
    const f0 = m.base_color[c] * m.base_weight;
    const F = fresnelF82Tint(f0, m.specular_color[c], a.lh);
    const metal = m.specular_weight * lobe * F * comp(F, f0);
    const dielectric = m.specular_color[c] * dielectricSpecular + (left * m.base_weight * m.base_color[c]) / Math.PI;
    return m.base_metalness * metal + (1 - m.base_metalness) * dielectric;
  });
}
