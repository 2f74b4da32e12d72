// microfacets, in words: the about text, the legend of the cut's colours, and the picture described for screen
// readers.
import { declareFormula, texNumber } from '../../core/framework/formula-registry.js';
import { DEG } from '../../math/angles.js';
import { smithG1 } from './model.js';
import { schema } from './schema.js';

export const TITLE = 'Microsurface';

export const ABOUT =
  'A cut through a rough surface, magnified: every facet is a tiny mirror. Yellow rays come from the light; ' +
  'a facet sends light to the eye only if its normal is the half vector h (marked in magenta). Black stretches ' +
  'are shadowed (the light cannot reach them), blue ones masked (the eye cannot see them). Some reflected rays ' +
  'hit the surface again (red): the microfacet BRDF drops that light. The plot ray-traces a profile of ' +
  '80 000 facets and compares the share of lit facets with Smith’s G1 for the same roughness.';

const key = (color, mark, text) => `<span style="color:${color}">${mark}</span> ${text}`;
export const LEGEND_HTML = [
  key('#e6a700', '━', 'light rays'),
  key('#d62728', '━', 'second bounce'),
  key('#cc79a7', '▮', 'facet normal = h'),
  key('#111', '▬', 'shadowed (solid)'),
  key('#0072b2', '▭', 'masked (hollow)'),
].join(' &nbsp; ');

/** The shadowed share, 1 − G1, as a percentage. */
export const shadowedShare = (g1, digits) => `${((1 - g1) * 100).toFixed(digits)}%`;

/** The picture in words; `hDeg` is the half vector's angle from the mean normal. */
export function describeCut(state, { measured, smith, twice, hDeg }) {
  const s = state;
  return (
    `Magnified cross-section of a rough surface, ${schema.kind.options[s.kind]}, α ${s.alpha}: ` +
    `${s.rays} rays from the light at ${s.lightTheta}°, eye at ${s.viewTheta}°, so the half vector h is ` +
    `${hDeg.toFixed(1)}° from the mean normal; facets along h are marked. Shadowed share of the facets facing ` +
    `the light: ${shadowedShare(measured, 1)} ray-traced, ${shadowedShare(smith, 1)} by Smith. ` +
    `${twice} of ${s.rays} rays hit the surface a second time${s.bounces ? ' (drawn in red)' : ''}.`
  );
}

const G1_TEX = {
  ggx: '\\frac{2\\nx }{\\nx  + \\sqrt{\\nx ^2 + \\alpha^2(1 - \\nx ^2)}}',
  beckmann: '\\frac{1}{1 + \\Lambda(a)},\\ a = \\frac{\\nx }{\\alpha\\sqrt{1 - \\nx ^2}}',
};

/** Smith's G1 of the chosen distribution at the light and the view, which the traced surface is set against. */
export const FORMULA = declareFormula('microfacets', (state) => {
  const cosL = Math.cos(state.lightTheta * DEG);
  const cosV = Math.cos(state.viewTheta * DEG);
  const [gl, gv] = [smithG1(state, cosL), smithG1(state, cosV)];
  const name = state.kind === 'ggx' ? 'GGX' : 'Beckmann';
  const g1 =
    `\\sym{kind}{G_{1,\\text{${name}}}(\\mathbf{x})} =` +
    ` ${G1_TEX[state.kind]},\\quad \\sym{alpha}{\\alpha = ${texNumber(state.alpha, 2)}}`;
  const at =
    `G_1(\\mathbf{l}) = ${texNumber(gl)}\\ (\\sym{lightTheta}{\\theta_l =` +
    ` ${texNumber(state.lightTheta, 0)}^\\circ}),\\quad ` +
    `G_1(\\mathbf{v}) = ${texNumber(gv)}\\ (\\sym{viewTheta}{\\theta_v =` +
    ` ${texNumber(state.viewTheta, 0)}^\\circ}),\\quad ` +
    `G_1(\\mathbf{l})\\,G_1(\\mathbf{v}) = ${texNumber(gl * gv)}`;
  return `\\begin{gathered}${g1}\\\\ ${at}\\end{gathered}`;
});
