// The material lab's words: what the widget is about, the terms it uses, and the captions and descriptions of
// what it shows.
import { declareFormula, texNumber, texText } from '../../core/framework/formula-registry.js';
import { ENVIRONMENTS } from '../../lab/environments.js';
import { materialOf } from '../../lab/lab-scene.js';
import { termEntry } from '../../math/catalogue/index.js';
import { brdfFromPunctualRadiance } from '../../math/brdf.js';
import { MERL_TEXTURE_BYTES } from '../measured-brdf/texture-size.js';
import { punctualAlone } from './model.js';
import { anisotropyOf, stretchesLobe } from '../../lab/lab-anisotropy.js';

export const ABOUT =
  'A shading model becomes a picture only with an illumination model. The left sphere is rendered the way a ' +
  'real-time renderer would (the method chosen for each light); the middle one solves the reflectance equation ' +
  'by Monte Carlo, adding samples until it converges; the right image is their difference. The punctual light ' +
  'is exact in both (it is a single direction: L = π f c_light (n·l)). The sphere light, the environment and ' +
  'ambient light are integrals that the approximations shortcut: a representative point, a prefiltered map with ' +
  'a DFG table (the split sum), a few importance samples, or the mirror direction alone. Each one uses the F, D ' +
  'and V chosen above where it has a form for them (a DFG table and a prefiltered map made for the chosen D and ' +
  'V; F = 1 gives A + B); the lines under the images say what stands in where it has none. Multiple scattering ' +
  'puts back the light the microfacet model drops (Kulla & Conty 2017, or Turquin 2019), in both images, so the ' +
  'error image shows what each method does with it. Drop an .hdr or .exr panorama on the widget to light it with ' +
  'your own environment, or a MERL .binary file (Matusik et al. 2003) to render a measured BRDF: its table is ' +
  `a 3-D texture of ${(MERL_TEXTURE_BYTES / 1e6).toFixed(2)} MB on the GPU, and only the reference and importance ` +
  'sampling have a form for it. Choose “Your GLSL” as the BRDF to render a whole f(l, v) you write: the ' +
  'reference samples it by GGX at the chosen α and by the cosine together (so it converges for any BRDF), and ' +
  'only the punctual and sphere lights and importance sampling have a form for it. Choose “OpenPBR Surface” (or a ' +
  'preset, or load a MaterialX .mtlx file) to render the layered material of today (Academy Software Foundation, ' +
  '2024) with its parameters grouped as its specification groups them; the bars under the images show what each ' +
  'layer adds under the punctual light and in the white furnace.';

export const TERMS_USED = [
  'microfacetBRDF',
  'dfgTableUv',
  'sampleGGXNormal',
  'sampleBeckmannNormal',
  'sampleCosine',
  'sampleCone',
  'sphereLightRepresentativeDir',
  'sphereLightNormalization',
  'equirectUv',
  'anisotropicBentReflection',
  'diffuseOrenNayar',
];

const fmt = (x, digits = 4) => (x === null || x === undefined ? '—' : x.toPrecision(digits));

/**
 * The lights on and the method each is shaded by, in words (the approximation's caption). A whole BRDF (a table,
 * the user's, OpenPBR) has only importance sampling for the environment and no ambient form: those lights are said
 * to be left out (the caption has room for no more), as the notes under the images explain (lab-approximations.js).
 */
export function methodText(st, lights) {
  const parts = [];
  const whole = st.brdfSource !== 'model';
  if (lights.punctual) parts.push('punctual (exact)');
  if (lights.sphere) {
    parts.push(`sphere light by ${st.areaMethod === 'centre' ? 'its centre' : 'representative point'}`);
  }
  if (lights.env) {
    const name = ENVIRONMENTS[st.environment].split(' (')[0].toLowerCase();
    const samples = st.envMethod === 'importance' ? `${st.samples} importance samples` : st.envMethod;
    parts.push(whole && st.envMethod !== 'importance' ? `${name} left out` : `${name} by ${samples}`);
  }
  if (lights.ambient) parts.push(whole ? 'ambient left out' : 'ambient');
  return parts.join(' + ') || 'no light on';
}

/** The captions over the three images. */
export const captions = (st, lights, stats) => [
  { image: 'approx', caption: `Approximation: ${methodText(st, lights)}` },
  stats.waiting
    ? { image: 'reference', caption: 'Reference: the one before the drag, started again once you let go' }
    : { image: 'reference', caption: `Reference: Monte Carlo, ${stats.samples} of ${stats.target} samples / pixel` },
  { image: 'error', caption: `Error |approx − reference|, 0 to ${st.errorScale}${stats.waiting ? ' (stale)' : ''}` },
];

/** The readout under the images: the approximation's GPU time and its error (stats), or why there is none. */
export function readoutHtml(st, stats, lights, resolution) {
  if (!Object.values(lights).some(Boolean)) {
    return '<p class="lab-empty">Every light is off: switch one on in the controls.</p>';
  }
  const converging = stats.waiting
    ? ' — against the reference before the drag (it waits until you let go)'
    : stats.samples < stats.target
      ? ' — reference still converging'
      : '';
  const time = `${fmt(stats.ms, 3)} ms for ${resolution}² pixels`;
  const error = `${fmt(stats.rms)} (radiance), ${fmt(stats.relative * 100, 3)} % of the reference’s RMS${converging}`;
  return `<table class="data-table compact"><tbody>
        <tr><th scope="row">GPU time of the approximation</th><td>${time}</td></tr>
        <tr><th scope="row">RMS error against the reference</th><td>${error}</td></tr>
        ${centreHtml(st, lights, stats.centre)}
        </tbody></table>`;
}

const rgbText = (rgb) =>
  rgb.every((x) => Math.abs(x - rgb[0]) < 5e-4) ? rgb[0].toFixed(3) : rgb.map((x) => x.toFixed(3)).join(', ');

/**
 * The readout's row for the sphere's centre (n = v): its radiance L in the approximation (`centre`, linear RGB),
 * and with the punctual light alone, L taken apart as π f c_light (n·l): f, and what L would be without the π.
 */
export function centreHtml(st, lights, centre) {
  if (!centre) return '';
  const L = `L = ${rgbText(centre)}`;
  const row = (head, text) => `<tr><th scope="row">${head}</th><td>${text}</td></tr>`;
  if (!punctualAlone(lights)) {
    return row(
      'Radiance at the sphere’s centre',
      `${L}, from every light that is on. With the punctual light alone it is L = π f c_light (n·l): the ` +
        'button below shows it for a white Lambert sphere.',
    );
  }
  const nl = lights.punctual.dir[2]; // n = v = z at the centre
  if (!(nl > 1e-6)) return row('Radiance at the sphere’s centre', `${L}: the light is behind it (n·l ≤ 0).`);
  const cnl = st.cLight * nl;
  const f = cnl > 0 ? centre.map((x) => brdfFromPunctualRadiance(x, nl, st.cLight)) : null;
  const apart = f
    ? `f = L / (π c_light (n·l)) = ${rgbText(f)} (1/π = 0.318 for a white Lambert surface). Without the π ` +
      `the centre would read L / π = ${rgbText(centre.map((x) => x / Math.PI))}.`
    : 'c_light = 0: no light arrives.';
  return row(
    'Radiance at the sphere’s centre, punctual light alone',
    `${L} against c_light (n·l) = ${st.cLight} × ${nl.toFixed(3)} = ${cnl.toFixed(3)}: L = π f c_light (n·l), ` +
      `so ${apart}`,
  );
}

/** What the canvas shows, for a screen reader: the material (or the measured table's `name`), the lights, the error. */
export function description(st, lights, stats, measuredName) {
  const errorWords =
    stats.samples < stats.target
      ? 'The reference is still converging.'
      : `RMS error ${fmt(stats.rms, 3)}, ${fmt(stats.relative * 100, 3)} % relative; ${fmt(stats.ms, 3)} ms.`;
  const model = st.material === 'manual' ? `F0 ${st.f0}, diffuse ${st.cdiff}` : st.material;
  const what = measuredName ? `the measured BRDF ${measuredName}` : `${model}, roughness α ${st.alpha}`;
  return (
    `Material lab. A sphere (${what}) lit by ${methodText(st, lights)}; beside it the Monte Carlo reference ` +
    `(${stats.target} samples per pixel) and the error image. ${errorWords}`
  );
}

export const NOTICES = {
  noMeasured: 'No MERL file has been dropped yet: drop a .binary file on the widget. Kept the model.',
  noFile: 'No environment file has been dropped yet: drop an .hdr or .exr panorama on the widget. Kept the studio.',
  dropText: 'Load an .hdr / .exr environment, a MERL .binary BRDF or a MaterialX .mtlx…',
  headOn: 'Check the π: a white Lambert sphere lit head-on by the punctual light alone',
  brushed: 'Brushed aluminium: an anisotropic GGX lobe on a machined disc, its brushing lines shown',
};

const short = (family, key) => texText(termEntry(family, key).short);

/**
 * The lab's BRDF as TeX: the diffuse and specular layers with their terms named (each tied to the control of
 * `keys`, the state key that chooses it, when the widget has one), then α and F0 of `material` (materialOf), and
 * the pair (αx, αy) of an `anisotropy` the lobe is stretched by (lab-anisotropy.js).
 */
export function brdfTex(terms, material, keys = {}, anisotropy = null) {
  const tie = (key, tex) => (keys[key] ? `\\sym{${keys[key]}}{${tex}}` : tex);
  const F = tie('F', terms.F === 'one' ? '1' : `F_{${short('fresnel', terms.F)}}`);
  // the user's stretched D or V (lab-anisotropy.js) in place of the chosen one
  const yours = (slot, key) => anisotropy?.[slot] === 'custom' && tie(key, `${slot}_{\\text{yours}}`);
  const D = yours('D', 'anisoD') || tie('D', `D_{${short('ndf', terms.D)}}`);
  const V = yours('V', 'anisoV') || tie('V', `V_{${short('visibility', terms.V)}}`);
  const single = `\\frac{${F}\\,${V}\\,${D}}{4}`;
  const compensated = {
    kullaConty: `${single} + ${tie('compensation', 'f_{\\text{ms}}')}`,
    turquin: `${tie('compensation', '\\left(1 + F_0\\frac{1 - E}{E}\\right)')}${single}`,
  };
  const specular = compensated[terms.compensation] ?? single;
  const diffuse = tie('diffuse', `f_{${short('diffuse', terms.diffuse)}}`);
  const layers = { both: `${diffuse} + ${specular}`, specular, diffuse }[terms.layers];
  const f0 = material.f0.every((x) => x === material.f0[0])
    ? texNumber(material.f0[0])
    : `(${material.f0.map((x) => texNumber(x)).join(',\\ ')})`;
  const params = `${tie('alpha', `\\alpha = ${texNumber(material.alpha, 3)}`)},\\ ${tie('f0', `F_0 = ${f0}`)}`;
  const pair = anisotropy
    ? `,\\ ${tie('anisotropy', `a = ${texNumber(anisotropy.strength, 2)}`)}:\\ (\\alpha_x, \\alpha_y) = ` +
      `(${anisotropy.alpha.map((x) => texNumber(x, 3)).join(',\\ ')})`
    : '';
  return `${tie('layers', 'f(\\mathbf{l},\\mathbf{v})')} = ${layers},\\quad ${params}${pair}`;
}

export const PUNCTUAL =
  'L_o = \\pi f(\\mathbf{l}_c,\\mathbf{v}) \\otimes \\mathbf{c}_{\\text{light}}(\\mathbf{n}\\cdot\\mathbf{l}_c)';
// the terms' names in the state are the catalogue's choice (F, D, V, diffuse, compensation): each ties to its own key
const TERM_KEYS = ['F', 'D', 'V', 'diffuse', 'layers', 'compensation'];
const KEYS = Object.fromEntries([...TERM_KEYS, 'alpha', 'anisoD', 'anisoV'].map((k) => [k, k]));

const F0_KEY = (state) => (state.material === 'manual' ? 'f0' : 'material');
/** A BRDF that is not the model's terms: named, not written out. */
const SOURCE_TEX = {
  measured: '\\sym{brdfSource}{f(\\mathbf{l}, \\mathbf{v}) = f_{\\text{measured}}\\ \\text{(a MERL table)}}',
  custom:
    '\\sym{brdfSource}{f(\\mathbf{l}, \\mathbf{v}) = f_{\\text{yours}}(\\mathbf{l}, \\mathbf{v})\\ ' +
    '\\text{(your GLSL)}}',
};

/** The lab's BRDF and, with the punctual light on, the talk's punctual-light equation with its c_light. */
export const FORMULA = declareFormula('material-lab', (state) => {
  const terms = Object.fromEntries(TERM_KEYS.map((k) => [k, state[k]]));
  const scene = { anisotropy: anisotropyOf(state), terms: { D: state.D, layers: state.layers } };
  const stretch = stretchesLobe(scene) ? scene.anisotropy : null;
  const f =
    SOURCE_TEX[state.brdfSource] ??
    brdfTex(terms, materialOf(state), { ...KEYS, f0: F0_KEY(state), anisotropy: 'anisotropy' }, stretch);
  if (!state.punctual) return f;
  const light =
    `${PUNCTUAL},\\quad \\sym{cLight}{\\mathbf{c}_{\\text{light}} = ${texNumber(state.cLight, 2)}},\\ ` +
    `\\sym{lightTheta}{\\theta = ${texNumber(state.lightTheta, 0)}^\\circ}`;
  return `\\begin{gathered}${f}\\\\ ${light}\\end{gathered}`;
});
