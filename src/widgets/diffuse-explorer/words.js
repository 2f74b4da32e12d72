// The diffuse explorer's words: what it shows, the functions it names, and its spheres described for screen readers.
import { declareFormula, texNumber, texYours } from '../../core/framework/formula-registry.js';
import { DEG } from '../../math/angles.js';
import { sigmaText } from '../../core/ui/sigma-range.js';
import { termLabel } from '../../math/catalogue/index.js';

export const TITLE = 'Diffuse explorer';

export const ABOUT =
  'Every sphere has a diffuse term only, lit by one punctual light (L = π f c_light (n·l), c_light = 1). ' +
  'Lambert’s f is a constant, so its brightness is just the cosine: bright where the surface faces the light, ' +
  'dark towards the terminator. The two trade-off models give the specular term first claim on the light, so ' +
  'they darken near the silhouette, where Fresnel reflection takes nearly everything; F0 sets how much they ' +
  'give up. Oren–Nayar models a surface of V-shaped grooves whose slopes spread by σ: grooves facing the viewer ' +
  'are also the lit ones when the light is behind the viewer, so the rim stays bright and the disc looks flat, ' +
  'like the full moon. Put the light at the centre of the pad, raise σ and compare the profiles; at σ = 0 both ' +
  'Oren–Nayar forms are exactly Lambert. σ is the spread of the facet tilt angle: beyond about 45° a Gaussian ' +
  'that wide would tilt over 4.6% of the facets past 90°, so the slider’s upper half (to 90°) extrapolates the ' +
  'model, and the plots say so. The last plot adds a smooth specular F(θv) to each diffuse albedo: above 1, the ' +
  'pair reflects more light than arrives. Fresnel-weighted Lambert is not normalised: head-on it returns ' +
  '(1 − F0)²·20/21 of c_diff (0.878 at F0 = 0.04). Choose Custom to draw a diffuse term you write in GLSL ' +
  'beside them (its α is σ in radians).';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'diffuseLambert',
  'diffuseFresnelWeighted',
  'diffuseAshikhminShirley',
  'diffuseOrenNayar',
  'diffuseOrenNayarQualitative',
  'fresnelSchlick',
];

/** The spheres in words: the parameters, the light and the models shown. */
export const describeSpheres = (state) =>
  `Spheres with a diffuse term only (c_diff ${state.cdiff}, F0 ${state.f0}, ${sigmaText(state.sigma)}), light ` +
  `${state.lightTheta}° from the view: ${state.diffuse.map((k) => termLabel('diffuse', k)).join(', ')}.`;

const C = '\\sym{cdiff}{\\mathbf{c}_{\\text{diff}}}';
const HALF5 = (x) => `\\left(1 - \\left(1 - \\tfrac{\\mathbf{n}\\cdot\\mathbf{${x}}}{2}\\right)^5\\right)`;
const ON_A = (s2) => 1 - (0.5 * s2) / (s2 + 0.33);
const ON_B = (s2) => (0.45 * s2) / (s2 + 0.09);

/** Each diffuse model as src/math/diffuse.js evaluates it, its constants computed from the state. */
const DIFFUSE_TEX = {
  custom: () => texYours('f', `${C}, \\mathbf{l}, \\mathbf{v}, \\alpha`, '\\alpha = \\sigma\\ \\text{in radians}'),
  lambert: (s) =>
    `f_{\\text{Lambert}} = \\frac{${C}}{\\pi} = \\frac{${texNumber(s.cdiff, 2)}}{\\pi} =` +
    ` ${texNumber(s.cdiff / Math.PI)}\\ \\mathrm{sr}^{-1}`,
  fresnelWeighted: (s) =>
    `f = (1 - F\\nl )(1 - F\\nv )\\frac{${C}}{\\pi},\\ ` +
    `\\sym{f0}{F_0 = ${texNumber(s.f0, 2)}},\\ \\frac{${C}}{\\pi} =` +
    ` ${texNumber(s.cdiff / Math.PI)}\\ \\mathrm{sr}^{-1}`,
  ashikhminShirley: (s) =>
    `f = \\frac{28}{23\\pi}${C}(1 - \\sym{f0}{F_0})${HALF5('l')}${HALF5('v')},\\ ` +
    `\\frac{28}{23\\pi}${C}(1 - F_0) = ${texNumber((28 / (23 * Math.PI)) * s.cdiff * (1 - s.f0))}\\ \\mathrm{sr}^{-1}`,
  orenNayar: (s, s2) =>
    `f = \\frac{${C}}{\\pi}\\left(C_1 + \\cos\\phi\\,C_2\\tan\\beta +` +
    ` (1 - |\\cos\\phi|)C_3\\tan\\tfrac{\\alpha + \\beta}{2}\\right)` +
    ` + 0.17\\frac{${C}^2}{\\pi}\\frac{\\sigma^2}{\\sigma^2 +` +
    ` 0.13}\\left(1 - \\cos\\phi\\left(\\tfrac{2\\beta}{\\pi}\\right)^2\\right),\\ ` +
    `C_1 = 1 - \\frac{0.5\\sigma^2}{\\sigma^2 + 0.33} = ${texNumber(ON_A(s2))}`,
  orenNayarQualitative: (s, s2) =>
    `f = \\frac{${C}}{\\pi}(A + B\\max(0, \\cos\\phi)\\sin\\alpha\\tan\\beta),\\ ` +
    `A = 1 - \\frac{0.5\\sigma^2}{\\sigma^2 + 0.33} = ${texNumber(ON_A(s2))},\\ B =` +
    ` \\frac{0.45\\sigma^2}{\\sigma^2 + 0.09} = ${texNumber(ON_B(s2))}`,
};

/** The first chosen diffuse model, with c_diff, F0 and σ (in radians, as the model reads it) substituted. */
export const FORMULA = declareFormula('diffuse-explorer', (state) => {
  const key = state.diffuse[0];
  if (!key) return '\\sym{diffuse}{\\text{no model chosen}}';
  const sigma = state.sigma * DEG;
  const line = `\\sym{diffuse}{${DIFFUSE_TEX[key](state, sigma * sigma)}}`;
  if (!key.startsWith('orenNayar')) return `${line},\\quad ${C} = ${texNumber(state.cdiff, 2)}`;
  const on =
    `\\alpha = \\max(\\theta_l, \\theta_v),\\ \\beta = \\min(\\theta_l, \\theta_v),\\ ` +
    `\\sym{sigma}{\\sigma = ${texNumber(state.sigma, 1)}^\\circ =` +
    ` ${texNumber(sigma, 3)}\\ \\text{rad}},\\ ${C} = ${texNumber(state.cdiff, 2)}`;
  return `\\begin{gathered}${line}\\\\ ${on}\\end{gathered}`;
});
