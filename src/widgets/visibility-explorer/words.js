// The visibility explorer's words: what it shows, the functions it names, and its pictures described for
// screen readers.
import { declareFormula, texNumber, texYours } from '../../core/framework/formula-registry.js';

export const TITLE = 'Visibility explorer';

export const ABOUT =
  'The plots show G = V·(n·l)(n·v), the share of microfacets that are neither shadowed nor masked, so that ' +
  'all terms share one scale. The implicit term is G = (n·l)(n·v): it falls too soon and is the same at every ' +
  'roughness. Change α and watch which curves move. The error plot measures each term against ' +
  'height-correlated Smith. With l and v mirrored about n, h = n and both Cook-Torrance and Kelemen give G = 1 ' +
  'exactly. On the spheres (GGX D, F = 1) the differences show at the silhouettes, where the ' +
  'angles are grazing. Choose Custom to draw a V you write in GLSL beside them, checked on the GPU beside the ' +
  'editor. The last plot goes beyond the talk, whose surfaces are isotropic: over an anisotropic surface, rougher ' +
  'along its tangent, G1 depends on the direction’s azimuth.';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'visibilityImplicit',
  'visibilityCookTorrance',
  'visibilityKelemen',
  'visibilitySmithGGXSeparable',
  'visibilitySmithGGXCorrelated',
  'visibilitySmithGGXCorrelatedFast',
  'visibilitySchlickGGX',
  'visibilitySmithBeckmannSeparable',
  'microfacetBRDF',
  'smithG1GGXAniso',
  'smithG1BeckmannAniso',
  'anisotropicAlphas',
];

/**
 * Under the azimuth plot: Smith's anisotropic Λ, and where each anisotropic G1 starts (along the tangent) and ends
 * (along the bitangent). curves: azimuth.js's, [GGX, Beckmann, …], over 0°–180° in steps of 1°.
 */
export function describeAzimuth(curves, [ax, ay], state) {
  const [ggx, beckmann] = curves;
  const ends = (c) => `from ${c.values[0].toFixed(4)} at φ = 0° to ${c.values[90].toFixed(4)} at φ = 90°`;
  return (
    `Smith’s Λ over an anisotropic surface is the isotropic Λ at the roughness projected on the direction’s ` +
    `azimuth, α(φ) = √(cos²φ·αx² + sin²φ·αy²) (Heitz 2014), here from αx = ${ax.toPrecision(3)} along the ` +
    `tangent to αy = ${ay.toPrecision(3)} along the bitangent. At θ = ${state.viewTheta}° from n, GGX’s G1 runs ` +
    `${ends(ggx)}, meeting the isotropic G1 at αx and at αy there; Beckmann’s runs ${ends(beckmann)}.`
  );
}

/** The x axis of both plots, by how l and v move. */
export const angleAxisLabel = (state) =>
  state.config === 'mirror'
    ? 'Angle of l and of v from n (degrees)'
    : `Light angle θl, view fixed at ${state.viewTheta}° (degrees)`;

/** Under the spheres: where to look, and how much brighter or darker each term is there than the reference. */
export function describeRim(ratios, state, deg) {
  const signed = (r) => {
    const pct = Math.round((r - 1) * 100);
    return `${pct > 0 ? '+' : pct < 0 ? '−' : '±'}${Math.abs(pct)}%`;
  };
  const each = ratios.map((r) => `${r.label} ${signed(r.ratio)}`).join(', ');
  return (
    `What to look for: the lit side, where the surface turns ${deg}° from you towards the light ` +
    `(${state.lightTheta}° from you). There each sphere is brighter or darker than the one with Smith GGX, ` +
    `height-correlated (the reference) by${each ? `: ${each}` : ' nothing: no other term chosen'}.`
  );
}

/** The spheres in words: the light, and each term's largest difference from height-correlated Smith. */
export function describeSpheres(curves, state) {
  const where = state.config === 'mirror' ? 'l and v mirrored' : `view at ${state.viewTheta}°`;
  const worst = curves.map((c) => `${c.label} ${c.worst.toFixed(1)}%`).join(', ') || 'no term chosen';
  return (
    `Spheres with GGX D at α ${state.alpha} and F = 1, light ${state.lightTheta}° from the view, ` +
    `exposure ${state.exposure}, one per visibility term. ` +
    `Largest difference from height-correlated Smith up to 80° (${where}): ${worst}.`
  );
}

const NL = '\\nl ';
const NV = '\\nv ';
const root = (c, a2) => `\\sqrt{${c}^2 + ${a2}(1 - ${c}^2)}`;
const g1 = (c, a2) => `\\frac{2${c}}{${c} + ${root(c, a2)}}`;

/** Each visibility term as it is evaluated (src/math/visibility.js), with α² (or k) substituted. */
const V_TEX = {
  custom: () => `V = ${texYours('V', '\\nl, \\nv, \\alpha')}`,
  implicit: () => 'V = 1,\\quad G_{\\text{implicit}} = \\nl \\nv ',
  cookTorrance: () =>
    `G_{\\text{ct}} = \\min\\left(1, \\frac{2\\nh ${NV}}{\\vh }, ` + `\\frac{2\\nh ${NL}}{\\vh }\\right)`,
  kelemen: () => 'V_{\\text{Kelemen}} = \\frac{1}{\\lh ^2}',
  smithGGXSeparable: (a2) =>
    `G_{\\text{s}} = G_{\\text{s1}}(\\mathbf{l})G_{\\text{s1}}(\\mathbf{v}),\\ ` +
    `G_{\\text{s1}}(\\mathbf{x}) = ${g1('\\nx ', a2)}`,
  smithGGXCorrelated: (a2) => `V = \\frac{2}{${NV}${root(NL, a2)} + ${NL}${root(NV, a2)}}`,
  smithGGXCorrelatedFast: (a2, a) => `V \\approx \\frac{2}{(1 - ${a})\\,2${NL}${NV} + ${a}(${NL} + ${NV})}`,
  schlickGGX: (a2, a, k) => `V = \\frac{1}{(${NL}(1 - ${k}) + ${k})(${NV}(1 - ${k}) + ${k})},\\ k = \\alpha/2`,
  smithBeckmannSeparable: (a2, a) =>
    `G_{\\text{s1}}(\\mathbf{x}) = \\frac{1}{1 + \\Lambda(c)},\\ c = \\frac{\\nx }{${a}\\sqrt{1 - \\nx ^2}}` +
    ',\\ \\Lambda(c) = \\tfrac{1}{2}\\left(\\frac{e^{-c^2}}{c\\sqrt{\\pi}} - \\operatorname{erfc} c\\right)',
};

/** V = G / ((n·l)(n·v)) and the first chosen term, with the state's α. */
export const FORMULA = declareFormula('visibility-explorer', (state) => {
  const key = state.V[0];
  const a = `\\sym{alpha}{${texNumber(state.alpha, 2)}}`;
  const a2 = `${texNumber(state.alpha ** 2)}`;
  const k = texNumber(state.alpha / 2);
  const V = 'V(\\mathbf{l},\\mathbf{v}) = \\frac{G(\\mathbf{l},\\mathbf{v},\\mathbf{h})}{\\nl \\nv }';
  const term = key ? `\\sym{V}{${V_TEX[key](a2, a, k)}}` : '\\sym{V}{\\text{no term chosen}}';
  return `\\begin{gathered}${V},\\quad \\alpha = ${a},\\ \\alpha^2 = ${a2}\\\\ ${term}\\end{gathered}`;
});
