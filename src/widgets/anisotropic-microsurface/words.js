// anisotropic-microsurface, in words: the about text, the table at the light's azimuth and the picture described
// for screen readers.
import { declareFormula, texNumber } from '../../core/framework/formula-registry.js';
import { smithG1BeckmannAniso } from '../../math/anisotropic.js';
import { directionOf } from './model.js';
import { WINDOW_CELLS } from './surface-view.js';

export const TITLE = 'Anisotropic microsurface, ray-traced';

export const ABOUT =
  'Beyond the talk: a 3-D rough surface whose bumps are stretched, seen from above and lit from the light’s ' +
  'direction; dark blue points lie in the shadow of other bumps, black ones face away from the light. With αx > αy ' +
  'the grooves run along b and the slopes are steeper along t, so a highlight stretches along t. Its heights are ' +
  'a Gaussian random field (a sum of ' +
  '400 waves with random phases), so its slopes follow anisotropic Beckmann, with a different roughness along the ' +
  'tangent t and the bitangent b. The plot ray-traces the share of facets facing the light that it reaches, G1, at ' +
  'thirteen azimuths, and sets it against Smith’s G1 with the roughness projected on the light’s azimuth, ' +
  'α(φ)² = cos²φ αx² + sin²φ αy² (Heitz 2014), for the pair (αx, αy) the surface’s own facets have. Averaged over ' +
  'all facets the two agree within about 0.01: a surface with no overhangs shows the light exactly its footprint, ' +
  'and Smith’s G1 keeps that same balance (the weak white furnace). What is left is this one surface’s slopes, only ' +
  'nearly Beckmann’s: a finite sum of waves leaves its slopes along t and b a few per cent correlated, so φ and ' +
  '180° − φ differ a little, besides the sampling of 12 000 rays per azimuth. Smith assumes more: that ' +
  'a facet’s chance of being shadowed does not depend on which way it tilts, as if heights along a ray were ' +
  'uncorrelated. On this smooth surface they are not: facets tilted away from the light sit on the far side of ' +
  'their bump and are shadowed more often (the green points), those tilted towards it less.';

/** Smith's G1 at the state's light for the roughness pair asked for (the facets' own differs a little). */
const smithAsked = (state) => smithG1BeckmannAniso(...directionOf(state.theta, state.phi), state.alphaX, state.alphaY);

/** The shadowed share, 1 − G1, as a percentage. */
const pct = (g1) => `${((1 - g1) * 100).toFixed(1)}%`;
const fix = (x) => x.toFixed(3);

/** The table at the light's azimuth: ray-traced and Smith's G1, the split by tilt, the α pairs. */
export function statsHtml(state, surface, { measured, smith }) {
  const row = (label, value) => `<tr><td>${label}</td><td>${value}</td></tr>`;
  const [ax, ay] = surface.alphas;
  return (
    `<table class="data-table compact"><caption>Light at θ ${state.theta}°, φ ${state.phi}°</caption><tbody>` +
    row('G1 ray-traced, all facets facing the light', fix(measured.g1)) +
    row('G1 by Smith, anisotropic Beckmann', fix(smith)) +
    row('G1 ray-traced, facets tilted towards the light', fix(measured.towards)) +
    row('G1 ray-traced, facets tilted away from the light', fix(measured.away)) +
    row('roughness of the surface’s own facets (αx, αy)', `(${fix(ax)}, ${fix(ay)})`) +
    row('roughness asked for (αx, αy)', `(${state.alphaX}, ${state.alphaY})`) +
    row('G1 by Smith at the roughness asked for (the formula’s)', fix(smithAsked(state))) +
    '</tbody></table>'
  );
}

/** The picture in words. */
export function describeSurface(state, { measured, smith }, shadowShare) {
  return (
    `A patch of ${WINDOW_CELLS} by ${WINDOW_CELLS} facets of a rough surface seen from above, its bumps stretched ` +
    `${state.alphaX < state.alphaY ? 'along t' : state.alphaX > state.alphaY ? 'along b' : 'in neither direction'}` +
    ` (αx ${state.alphaX}, αy ${state.alphaY}), lit from ${state.theta}° off the normal at azimuth ${state.phi}° ` +
    `from t; ${(shadowShare * 100).toFixed(0)}% of the patch is in shadow or faces away. Of the facets facing the ` +
    `light, ${pct(measured.g1)} are shadowed ray-traced and ${pct(smith)} by Smith; ${pct(measured.away)} of those ` +
    `tilted away from the light and ${pct(measured.towards)} of those tilted towards it.`
  );
}

/** Smith's anisotropic Beckmann G1 at the state's light, for the pair asked for (the table's is the facets' own). */
export const FORMULA = declareFormula('anisotropic-microsurface', (state) => {
  const g1 = smithAsked(state);
  const smith =
    'G_1(\\mathbf{w}) = \\frac{1}{1 + \\Lambda(a)},\\ a = \\frac{\\cot\\theta}{\\alpha(\\phi)},\\\\ ' +
    '\\alpha(\\phi) = \\sqrt{\\cos^2\\phi\\, \\alpha_x^2 + \\sin^2\\phi\\, \\alpha_y^2}';
  const sym = (key, tex, x, digits) => `\\sym{${key}}{${tex} = ${texNumber(x, digits)}${digits ? '' : '^\\circ'}}`;
  const at =
    [sym('alphaX', '\\alpha_x', state.alphaX, 2), sym('alphaY', '\\alpha_y', state.alphaY, 2)].join(',\\ ') +
    `\\\\ ${sym('theta', '\\theta', state.theta, 0)},\\ ${sym('phi', '\\phi', state.phi, 0)}:` +
    `\\quad G_1 = ${texNumber(g1)}`;
  return `\\begin{gathered}${smith}\\\\ ${at}\\end{gathered}`;
});
