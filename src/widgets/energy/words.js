// The white furnace's words: what it shows, the functions it names, and its spheres described for screen readers.
import { declareFormula, texNumber } from '../../core/framework/formula-registry.js';
import { albedoGGX } from '../../math/integrate.js';

export const TITLE = 'White furnace';

export const ABOUT =
  'In a uniform white environment a surface that loses no energy looks exactly as bright as its ' +
  'surroundings: it disappears. These spheres use GGX with height-correlated Smith and F = 1. Smooth ones ' +
  'nearly vanish; rough ones turn grey, most of all at the centre, because light blocked by one microfacet is ' +
  'simply dropped instead of bouncing on (the talk’s multiple-bounce slide). The plots give E(μ) = ∫ f (n·l) dω ' +
  'by deterministic quadrature over the microfacet normals, and each sphere pixel reads E(n·v) from a texture ' +
  'precomputed with it; the table below gives E head-on and its cosine-weighted average over all directions. ' +
  'Energy compensation puts the dropped light back: Kulla & Conty (2017) add a second, nearly diffuse lobe, ' +
  'Turquin (2019) scales the first; with F = 1 both make every sphere vanish. Below, a coloured metal shows what ' +
  'they cost and buy against the random walk on the microsurface (Heitz et al. 2016), the light followed from ' +
  'facet to facet.';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'dfgTableUv',
  'visibilitySmithGGXCorrelated',
  'ndfGGX',
  'specularAlbedoKullaConty',
  'specularAlbedoTurquin',
];

const rgbText = (rgb) => rgb.map((x) => x.toFixed(2)).join(', ');

/**
 * The furnace spheres and the metal in words: each α's albedo and loss, and the metal head-on with single
 * scattering and the random walk. `compensation` is the chosen compensation's label, null for none.
 */
export function describeFurnace(sweep, compensation, metal) {
  const compensated = compensation ? ` With ${compensation} every sphere reflects all of it and vanishes.` : '';
  const albedos = sweep.map(
    (d) =>
      `α ${d.alpha}: albedo ${d.atNormal.toFixed(3)} head-on, ${d.avg.toFixed(3)} on average, ` +
      `${((1 - d.avg) * 100).toFixed(1)}% lost`,
  );
  const walk = metal.walk ? rgbText(metal.walk[0].albedo) : 'still running';
  return (
    'Spheres in a uniform white environment (F = 1); a sphere that loses no energy vanishes into it.' +
    `${compensated} ${albedos.join('; ') || 'No roughness chosen'}. ` +
    `${metal.metal.name} at α ${metal.alpha} head-on: single scattering ${rgbText(metal.curves.none[0])}, ` +
    `random walk ${walk} (R, G, B).`
  );
}

const E_OF = 'E(\\mu_o) = \\int_\\Omega f(\\mathbf{l},\\mathbf{v})\\nl \\,d\\omega_l';
const E_AVG = 'E_{\\text{avg}}';
const F_AVG = 'F_{\\text{avg}}';
// both with their Fresnel terms, as src/math/multiple-scattering.js evaluates them (the spheres' F = 1 makes
// F_ms = 1 and Turquin's factor 1/E)
const COMPENSATION_TEX = {
  none: 'f = f_{\\text{ss}}\\quad \\text{(single scattering only)}',
  kullaConty:
    `f = f_{\\text{ss}} + F_{\\text{ms}}\\,f_{\\text{ms}},\\ f_{\\text{ms}} =` +
    ` \\frac{(1 - E(\\mu_o))(1 - E(\\mu_i))}{\\pi(1 - ${E_AVG})},\\ ` +
    `F_{\\text{ms}} = \\frac{${F_AVG}^2\\,${E_AVG}}{1 - ${F_AVG}(1 - ${E_AVG})},\\ ` +
    `${F_AVG} = F_0 + \\frac{1 - F_0}{21}`,
  turquin: 'f = f_{\\text{ss}}\\left(1 + F_0\\,\\frac{1 - E(\\mu_o)}{E(\\mu_o)}\\right)',
};
let memo = { alpha: NaN, E: 0 }; // E head-on by quadrature: once per roughness
const headOn = (alpha) => {
  if (memo.alpha !== alpha) memo = { alpha, E: albedoGGX(1, alpha) };
  return memo.E;
};

/** The furnace's albedo integral, the chosen compensation, and E head-on at the metal's roughness. */
export const FORMULA = declareFormula('energy', (state) => {
  const compensation = `\\sym{compensation}{${COMPENSATION_TEX[state.compensation]}}`;
  const E = headOn(state.metalAlpha);
  const metal =
    `E(1) = ${texNumber(E)},\\ 1 - E(1) = ${texNumber(1 - E)}\\ \\text{lost at}\\ ` +
    `\\sym{metalAlpha}{\\alpha = ${texNumber(state.metalAlpha, 2)}}`;
  return (
    `\\begin{gathered}${E_OF}\\ (F = 1,\\ D_{\\text{GGX}},\\ ` +
    `V_{\\text{Smith corr.}})\\\\ ${compensation}\\\\ ${metal}\\end{gathered}`
  );
});
