// The BRDF lobe's words: what it shows, the functions it names, and its pictures described for screen readers.
import {
  TEX_YOURS_NOTE,
  declareFormula,
  texNumber,
  texYours,
  texYoursTerm,
} from '../../core/framework/formula-registry.js';
import { brdfAngles } from '../../math/brdf.js';
import { termEntry } from '../../math/catalogue/index.js';
import { brdfSpec, factorsAt, lightDir, lobePeak, viewOf } from './model.js';
import { viewAzimuth } from './azimuths.js';
import { LAYER_KEYS, OPENPBR_LAYERS, layerLuminances, openPbrSpec } from './openpbr-lobe.js';

export const TITLE = 'BRDF lobe';

export const ABOUT =
  'Drag l or v on the polar plot (or focus it and use the arrow keys). The lobe is f(l, v) for every view ' +
  'direction: turn off D and the highlight’s shape is gone; turn off the denominator and the lobe stops ' +
  'growing at grazing angles (that denominator, with F, is why at moderate roughness f itself is largest ' +
  'towards the horizon, while at α = 0.1 it peaks near the mirror direction); turn off G and nothing dims at ' +
  'the horizon. × n·v multiplies the lobe by the cosine of the view, showing how much light leaves towards ' +
  'each direction; the reflectance equation’s cosine is another one, n·l, of the incoming light. Roughness is ' +
  'GGX’s α; other NDFs take the parameters that give them the same half width. The image over (θh, θd) shows ' +
  'the same BRDF in the angles it really depends on; the albedo plot integrates it over all light directions. ' +
  'Multiple scattering adds, dotted, the light that bounces between microfacets before it leaves (Kulla & ' +
  'Conty 2017), nearly diffuse in shape, with dots from the random walk on the microsurface (Heitz et al. ' +
  '2016) that it approximates. Choose Custom in A’s D, V or F menu, or as A’s whole BRDF, to draw a term ' +
  'you write in GLSL: it is checked on the GPU beside the editor, and B stays a catalogue term to compare with. ' +
  'Beyond the talk, whose BRDFs are isotropic: the light has an azimuth φl from the surface’s tangent t (the ' +
  'plane of incidence goes through it) and the view its own, Δφ off that plane (Page Up/Down and [ ] on the ' +
  'polar plot), and A’s anisotropy stretches GGX or Beckmann along the tangent (Heitz 2014’s forms; (αx, αy) ' +
  'by Burley 2012, glTF’s KHR_materials_anisotropy or OpenPBR 1.1), with height-correlated Smith GGX then ' +
  'anisotropic too. Turn φl: an isotropic lobe stays the same, an anisotropic one is widest along the tangent. ' +
  'The polar plot stays in the plane of incidence; a view off it is a hollow handle at its θv. ' +
  'Past the talk, A’s model OpenPBR Surface (2024) stacks these terms into a base, its specular lobe, a coat and ' +
  'a fuzz (parameters in its folder, by the specification’s names): the lobe is then the luminance of its RGB ' +
  'value, each line one layer’s part of it, and the wire grid the part of the layer chosen; F, D, G and the ' +
  'denominator are not switches of it.';

/** The functions behind the pictures, linked to their rows on the parity page. */
export const TERMS_USED = [
  'microfacetBRDF',
  'fresnelSchlick',
  'ndfGGX',
  'ndfBeckmann',
  'ndfBlinnPhong',
  'ndfABC',
  'ndfSGD',
  'visibilitySmithGGXCorrelated',
  'multipleScatteringKullaConty',
  'fresnelMultipleScatteringKullaConty',
  'ndfGGXAniso',
  'ndfBeckmannAniso',
  'visibilitySmithGGXCorrelatedAniso',
  'anisotropicAlphas',
];

/** The multiple-scattering lobe in words (empty when it is off). */
function multipleWords(state, ms) {
  if (!state.multiple) return '';
  if (!ms.lobe) return ' Multiple scattering is shown for GGX with height-correlated Smith only: choose those for A.';
  const at = (theta) => ms.lobe[Math.round((theta + 89) * 2)][1];
  const walk = ms.points.find((p) => p[0] === 5);
  return (
    ` Dotted: the multiple-scattering lobe of Kulla & Conty (${at(0).toPrecision(3)} /sr at 0°, ` +
    `${at(60).toPrecision(3)} at 60°), with dots from the random walk ` +
    `(${walk[1].toPrecision(3)} ± ${walk[2].toPrecision(1)} at 5°).`
  );
}

/** The polar plot in words: what is drawn, with which factors off, where each lobe peaks. */
export function describePolar(state, scene) {
  const { A, B, lobeA, lobeB, ms } = scene;
  const off = A.openpbr
    ? [] // OpenPBR has no factors to switch
    : ['F', 'D', 'G'].filter((k) => !state[`use${k}`]).concat(state.useDenominator ? [] : ['the denominator']);
  const what =
    `${state.cosine ? 'f(l, v) × n·v' : 'f(l, v)'} for ${A.label}${B ? ` and, dashed, ${B.label}` : ''}` +
    `${off.length ? ` with ${off.join(', ')} switched off` : ''}`;
  const peaks = [
    [A, lobeA],
    [B, lobeB],
  ]
    .filter(([p]) => p)
    .map(([p, lobe]) => {
      const [theta, value] = lobePeak(lobe);
      return `${p.label.slice(0, 1)} peaks at ${theta.toFixed(1)}° (${value.toPrecision(3)} /sr)`;
    });
  const layers = (scene.layers?.parts ?? []).map(({ key, lobe }) => {
    const [theta, value] = lobePeak(lobe);
    return `${OPENPBR_LAYERS[key].label} peaks at ${theta.toFixed(1)}° (${value.toPrecision(3)} /sr)`;
  });
  if (layers.length) peaks.push(`Lines, A's layers' parts of its luminance: ${layers.join('; ')}`);
  const offPlane = state.viewPhi ? ` (${state.viewPhi}° off the plane: the hollow handle)` : '';
  return (
    `Polar plot in the plane of incidence: ${what}. Light ${state.lightTheta}° from n on the left, view at ` +
    `${state.viewTheta}°${offPlane}, mirror direction at ${state.lightTheta}°. ${peaks.join('; ')}.` +
    multipleWords(state, ms)
  );
}

/** The 3-D lobe in words. */
export function describeLobe3d(state, scene) {
  const { A, B, max } = scene;
  const layer =
    !B && scene.layers?.fLayer
      ? ` (solid) and its ${OPENPBR_LAYERS[state.openpbrLayer].label} part` + ' (wireframe)'
      : '';
  return (
    `3-D lobe of ${A.label}${B ? ` (solid) and ${B.label} (wireframe)` : layer} over the hemisphere, light ` +
    `${state.lightTheta}° from n; each direction's distance from the centre is ${state.cosine ? 'f × n·v' : 'f'}, ` +
    `scaled to ${max.toPrecision(3)}. Arrows: n, l, v, h and the mirror direction. The plane of incidence (the ` +
    `blue pane) goes through the light's azimuth, ${state.lightPhi}° about n from the tangent t (the dark red ` +
    `arrow); the view is ${state.viewPhi}° off it, at ${viewAzimuth(state)}° from t.` +
    (A.aniso
      ? ` A is anisotropic, (αx, αy) = (${A.aniso.pair.map((x) => x.toPrecision(3)).join(', ')}): its lobe ` +
        `stretches along t${A.aniso.V ? '' : `; its V stays isotropic at α ${state.alpha}`}.`
      : '')
  );
}

/** A (θh, θd) image's BRDF in words. */
export const describeImage = (state, p, alpha) => `${p.label}, α ${alpha}, F0 ${state.f0}, at φd ${state.phiD}°`;

let memo = { key: '', spec: null }; // BRDF A's matched parameters: a root search for an NDF other than GGX
function specA(state) {
  const key = [
    state.D,
    state.V,
    state.F,
    state.f0,
    state.alpha,
    state.anisotropy,
    state.convention,
    state.lightPhi,
  ].join('|');
  if (memo.key !== key) memo = { key, spec: brdfSpec(state, 'A') };
  return memo.spec;
}

/** The symbolic BRDF A with the switched-off factors left out, each tied to its switch. */
function symbolic(state) {
  const top = [
    state.useF && '\\sym{useF}{F(\\mathbf{l},\\mathbf{h})}',
    state.useG && '\\sym{useG}{G(\\mathbf{l},\\mathbf{v},\\mathbf{h})}',
    state.useD && '\\sym{useD}{D(\\mathbf{h})}',
  ].filter(Boolean);
  const bottom = '\\sym{useDenominator}{4\\nl \\nv }';
  const numerator = top.join('\\,') || '1';
  return state.useDenominator ? `\\frac{${numerator}}{${bottom}}` : numerator;
}

/** The light's and view's angles; their azimuths when they matter (an anisotropic A, or a view off the plane). */
const LIGHT_VIEW = (state) =>
  `\\sym{lightTheta}{\\theta_l = ${texNumber(state.lightTheta, 1)}^\\circ},\\ ` +
  `\\sym{viewTheta}{\\theta_v = ${texNumber(state.viewTheta, 1)}^\\circ}` +
  (state.anisotropy > 0 || state.viewPhi
    ? `,\\ \\sym{lightPhi}{\\phi_l = ${texNumber(state.lightPhi, 1)}^\\circ},\\ ` +
      `\\sym{viewPhi}{\\Delta\\phi = ${texNumber(state.viewPhi, 1)}^\\circ}`
    : '');

/** A's D, G and F as named in the formula: a catalogue term, or the user's (named as the explorers name it). */
function termsTex(state) {
  const D =
    state.D === 'custom' ? texYoursTerm('D', '\\nh, \\alpha') : `D_{\\text{${termEntry('ndf', state.D).short}}}`;
  const G =
    state.V === 'custom'
      ? `V\\,\\nl \\nv ,\\ V = ${texYoursTerm('V', '\\nl, \\nv, \\alpha')}`
      : `V_{\\text{${termEntry('visibility', state.V).short}}}\\,\\nl \\nv `;
  const F = {
    one: '\\sym{F}{F = 1}',
    schlick: '\\sym{F}{F_{\\text{Schlick}}}',
    custom: `\\sym{F}{F = ${texYoursTerm('F', 'F_0, \\lh ')}}`,
  }[state.F];
  return `D = \\sym{D}{${D}},\\ G = \\sym{V}{${G}},\\ ${F}`;
}

/**
 * A's factors at (l, v) as numbers, a term the user wrote as its symbol: its values are read back from the GPU
 * after the formula is written (they are in the readout's table).
 */
function valuesTex(state, t, a) {
  const n = (x) => texNumber(x, 3);
  const yours = (k) => state[k] === 'custom';
  const numbers = [
    state.useF && (yours('F') ? 'F_{\\text{yours}}' : n(t.F)),
    state.useG && (yours('V') ? 'G_{\\text{yours}}' : n(t.G)),
    state.useD && (yours('D') ? 'D_{\\text{yours}}' : n(t.D)),
  ].filter(Boolean);
  const top = numbers.join('\\cdot ') || '1';
  const values = state.useDenominator ? `\\frac{${top}}{4\\cdot ${n(a.nl)}\\cdot ${n(a.nv)}}` : top;
  const anyYours = ['F', 'D', 'V'].some(yours);
  return anyYours
    ? `${values}\\ \\text{(your terms: their values are in the table)}`
    : `${values} = ${n(t.f)}\\ \\mathrm{sr}^{-1}`;
}

/** OpenPBR's lobe at (l, v): the luminance of each layer's part, already weighted by the layers above it. */
function openPbrTex(state) {
  const y = layerLuminances(lightDir(state.lightTheta), viewOf(state), openPbrSpec(state));
  const names = { specular: 'spec', diffuse: 'diff', metal: 'metal', coat: 'coat', fuzz: 'fuzz' };
  const sum = LAYER_KEYS.map((k) => `Y_{\\text{${names[k]}}}`).join(' + ');
  const values = LAYER_KEYS.map((k) => texNumber(y[k], 4)).join(' + ');
  return (
    `\\begin{gathered}Y(f) = ${sum}\\\\ = ${values} = ${texNumber(y.all, 4)}\\ \\mathrm{sr}^{-1}\\\\ ` +
    `${LIGHT_VIEW(state)}\\end{gathered}`
  );
}

/**
 * BRDF A at the light and view of the sliders: the factors, their values and f, in 1/sr; a whole BRDF the user
 * wrote has no factors: it is named, with the angles it is read at.
 */
export const FORMULA = declareFormula('brdf-lobe', (state) => {
  if (state.brdf === 'openpbr') return openPbrTex(state);
  if (state.brdf === 'custom') {
    const f = `\\sym{brdf}{f(\\mathbf{l},\\mathbf{v}) = ${texYours('f', '\\mathbf{l}, \\mathbf{v}')}}`;
    return `\\begin{gathered}${f}\\\\ ${LIGHT_VIEW(state)}\\end{gathered}`;
  }
  const p = specA(state);
  const [l, v] = [lightDir(state.lightTheta), viewOf(state)];
  const a = brdfAngles(l, v);
  const f = `f(\\mathbf{l},\\mathbf{v}) = ${symbolic(state)} = ${valuesTex(state, factorsAt(l, v, a, p), a)}`;
  const f0 = state.F === 'one' ? '' : `\\sym{f0}{F_0 = ${texNumber(state.f0, 3)}},\\ `;
  const angles = `${f0}\\sym{alpha}{\\alpha = ${texNumber(state.alpha, 2)}},\\ ${LIGHT_VIEW(state)}`;
  // a term of the user's makes the lines longer: the parameters get a line of their own, with the note
  const yours = ['F', 'D', 'V'].some((k) => state[k] === 'custom');
  const rest = yours ? `\\\\ ${angles}${TEX_YOURS_NOTE}` : `,\\ ${angles}`;
  return `\\begin{gathered}${f}\\\\ ${termsTex(state)}${rest}\\end{gathered}`;
});
