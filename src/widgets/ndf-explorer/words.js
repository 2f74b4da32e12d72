// The NDF explorer's words: what it shows, the functions it names, and its pictures described for screen readers.
import { declareFormula, texNumber, texYours } from '../../core/framework/formula-registry.js';
import { DEG } from '../../math/angles.js';
import { matchNdfWidths } from '../../math/ndf-width.js';

export const TITLE = 'NDF explorer';

export const ABOUT =
  'Each NDF is given the same half width at half maximum (the angle where D drops to half its peak), so the ' +
  'cores of the lobes match and only their shapes differ. The log plot shows the tails: GGX, ABC and SGD keep ' +
  'far more microfacets at large angles than Beckmann or Blinn-Phong, which is the halo around their highlights. ' +
  'Raise the exposure to see it. The spheres use F = 1 and V = 1 so that only D differs. The table integrates ' +
  'each D·(n·m) over the hemisphere: a density must give 1. Opened from the measured-BRDF widget (BRDF page), ' +
  'the log plot adds the NDF a measurement implies (black) and puts every curve over its own peak, so the ' +
  'measured tail is read against the five shapes at the fitted width. Choose Custom to draw a D you write in ' +
  'GLSL as a sixth curve and sphere, at GGX’s α for the width, checked on the GPU beside the editor. ' +
  'Anisotropy goes beyond the talk, whose NDFs are all isotropic: it stretches GGX and Beckmann along a ' +
  'tangent (Heitz 2014’s forms), the tangent running left to right across every sphere, and the slope maps show ' +
  'D over the hemisphere of h. How one roughness and an anisotropy become the pair (αx, αy) differs between ' +
  'Burley 2012, glTF’s KHR_materials_anisotropy and OpenPBR 1.1: the note under the maps says how.';

/** The conventions of anisotropicAlphas (src/math/anisotropic.js), as the menu names them. */
export const CONVENTION_LABELS = {
  burley2012: 'Burley 2012 (Disney)',
  gltf: 'glTF KHR_materials_anisotropy',
  openpbr: 'OpenPBR 1.1',
};

/** What each convention keeps, in words (the forms of anisotropicAlphas). */
const CONVENTION_RULES = {
  burley2012: 'αx = α/s, αy = α·s with s = √(1 − 0.9a): the geometric mean √(αx·αy) stays α',
  gltf: 'αx = α + (1 − α)a², αy = α: the tangent’s roughness rises towards 1, the bitangent’s stays α',
  openpbr: 'αx = α·√(2/(1 + (1 − a)²)), αy = (1 − a)·αx: the mean of the squares (αx² + αy²)/2 stays α²',
};

const pairText = ([ax, ay]) => `(${ax.toPrecision(3)}, ${ay.toPrecision(3)})`;
const widthText = (w) => (w === null ? 'no half maximum (D does not fall to half)' : `${w.toFixed(1)}°`);

/**
 * The note under the slope maps: the chosen convention's rule, the three conventions' pairs at the matched α, and
 * each anisotropic lobe's half width along t and b. `pairs` is { convention: [αx, αy] } at α, the matched α of
 * the NDF `of` (the first lobe's).
 */
export function describeAnisotropy(lobes, state, { alpha, of }, pairs) {
  if (!lobes.length) return 'Choose GGX or Beckmann to see an anisotropic lobe.';
  const a = state.anisotropy.toFixed(2);
  const others = Object.entries(pairs)
    .map(([k, pair]) => `${CONVENTION_LABELS[k]} ${pairText(pair)}`)
    .join(', ');
  const widths = lobes
    .map((l) => `${l.label} ${widthText(l.widths[0])} along the tangent, ${widthText(l.widths[1])} along the bitangent`)
    .join('; ');
  return (
    `${CONVENTION_LABELS[state.convention]}: ${CONVENTION_RULES[state.convention]}. At α = ${alpha.toPrecision(3)} ` +
    `(${of}’s at a half width of ${state.hwhm}°) and anisotropy a = ${a}, (αx, αy) is ${others}. ` +
    `Half widths: ${widths}.`
  );
}

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'ndfBlinnPhong',
  'ndfBeckmann',
  'ndfGGX',
  'ndfABC',
  'ndfSGD',
  'microfacetBRDF',
  'ndfGGXAniso',
  'ndfBeckmannAniso',
  'anisotropicAlphas',
];

/** An NDF's matched parameters in words: "exponent 41.2", "a1 …, a2 …", "α …, p …" or "α …". */
export const describeParams = (key, p) =>
  key === 'blinnPhong'
    ? `exponent ${p.exponent.toFixed(1)}`
    : key === 'abc'
      ? `a1 ${p.a1.toFixed(2)}, a2 ${p.a2.toFixed(2)}`
      : key === 'sgd'
        ? `α ${p.alpha.toFixed(4)}, p ${p.p.toFixed(2)}`
        : `α ${p.alpha.toFixed(4)}`;

/** The spheres in words: the light, and each NDF with its parameters and peak (an anisotropic one, its pair). */
export function describeSpheres(curves, state) {
  const each = curves.map((c) =>
    c.aniso && state.anisotropy > 0
      ? `${c.aniso.label} ((αx, αy) ${pairText(c.aniso.pair)}, stretched along the tangent, left to right)`
      : `${c.label} (${describeParams(c.key, c.p)}, peak D ${c.values[0].toPrecision(3)} /sr)`,
  );
  return (
    `Spheres lit by one small light ${state.lightTheta}° from the view, exposure ${state.exposure}, F = 1 and ` +
    `V = 1, one per NDF at a half width of ${state.hwhm}°: ${each.join(', ') || 'none chosen'}.`
  );
}

const SUPERSCRIPT = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };
/** A small ratio as people write it: 7.8 × 10⁻³ (0 where src/math cuts the far tail to 0, as the GPU must). */
const scientific = (x) => {
  if (x === 0) return '0 (too far down to compute)';
  const [mantissa, exponent] = x.toExponential(1).split('e');
  const power = [...String(Number(exponent))].map((ch) => SUPERSCRIPT[ch]).join('');
  return exponent === '+0' ? mantissa : `${mantissa} × 10${power}`;
};

/** The log plot's note: which tail is longest at this width, and how much of its peak each keeps at TAIL_DEG. */
export function describeTails(tails, state, deg) {
  if (tails.length < 2) return '';
  const [first, ...rest] = tails;
  const others = rest.map((t) => `${t.label} ${scientific(t.ratio)}`).join(', ');
  return (
    `Longest tail at a half width of ${state.hwhm}°: ${first.label}. At θh = ${deg}° it still has ` +
    `${scientific(first.ratio)} of its peak; ${others}.`
  );
}

const NM = '\\nm ';
const TAN2 = `\\frac{1 - ${NM}^2}{${NM}^2}`;

// GGX, Beckmann and Blinn-Phong at half width θ: D(θ) = D(0)/2 solved in closed form (the model searches)
const matchedGGX = (t) => Math.sqrt(Math.sin(t) ** 2 / (Math.SQRT2 - Math.cos(t) ** 2));
const matchedBeckmann = (t) => Math.tan(t) / Math.sqrt(Math.LN2 - 4 * Math.log(Math.cos(t)));
const matchedPhong = (t) => Math.log(0.5) / Math.log(Math.cos(t));

let memo = { key: '', params: null }; // ABC's and SGD's widths have no closed form: one search per setting
function searched(state) {
  const key = `${state.hwhm}|${state.abcA2}|${state.sgdP}`;
  if (memo.key !== key) memo = { key, params: matchNdfWidths(state.hwhm, state) };
  return memo.params;
}

/** NDF `key` as the talk writes it, and its parameters at the state's matched width (half width t, radians). */
const NDF_TEX = {
  custom: (s, t) => [texYours('D', `${NM}, \\alpha_{tr}`), `\\alpha_{tr} = ${texNumber(matchedGGX(t))}`],
  ggx: (s, t) => [
    `D_{tr}(\\mathbf{m}) = \\frac{\\alpha_{tr}^2}{\\pi(${NM}^2(\\alpha_{tr}^2 - 1) + 1)^2}`,
    `\\alpha_{tr} = ${texNumber(matchedGGX(t))}`,
  ],
  beckmann: (s, t) => [
    `D_b(\\mathbf{m}) = \\frac{1}{\\pi\\alpha_b^2 ${NM}^4}\\,e^{-${TAN2}\\,/\\,\\alpha_b^2}`,
    `\\alpha_b = ${texNumber(matchedBeckmann(t))}`,
  ],
  blinnPhong: (s, t) => [
    `D_p(\\mathbf{m}) = \\frac{\\alpha_p + 2}{2\\pi}${NM}^{\\alpha_p}`,
    `\\alpha_p = ${texNumber(matchedPhong(t), 1)}`,
  ],
  abc: (s) => [
    `D_{abc}(\\mathbf{m}) = \\frac{1}{N}\\,\\frac{1}{(1 + \\alpha_{abc1}(1 - ${NM}))^{\\alpha_{abc2}}}`,
    `\\alpha_{abc1} = ${texNumber(searched(s).abc.a1, 2)},\\ \\sym{abcA2}{\\alpha_{abc2} = ${texNumber(s.abcA2, 2)}}` +
      ',\\ N\\text{: normalisation}',
  ],
  sgd: (s) => [
    `D_{sgd}(\\mathbf{m}) = \\frac{p_{22}\\left[${TAN2}\\right]}{\\pi ${NM}^4}`,
    `\\alpha = ${texNumber(searched(s).sgd.alpha)},\\ \\sym{sgdP}{p = ${texNumber(s.sgdP, 2)}}`,
  ],
};

/** The first chosen NDF, with the parameters that give it the matched half width. */
export const FORMULA = declareFormula('ndf-explorer', (state) => {
  const key = state.D[0];
  if (!key) return '\\sym{D}{\\text{no distribution chosen}}';
  const [D, params] = NDF_TEX[key](state, state.hwhm * DEG);
  const width =
    `D(\\theta_{1/2}) = \\tfrac{1}{2}D(0),\\quad \\sym{hwhm}{\\theta_{1/2} =` + ` ${texNumber(state.hwhm, 1)}^\\circ}`;
  return `\\begin{gathered}\\sym{D}{${D}},\\quad ${params}\\\\ ${width}\\end{gathered}`;
});
