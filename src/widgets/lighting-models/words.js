// The lighting-models widget's words: what it is about, where each model fails, the table and the description.
import { declareFormula } from '../../core/framework/formula-registry.js';
import { materialOf } from '../../lab/lab-scene.js';
import { PUNCTUAL, brdfTex } from '../material-lab/words.js';
import { TERMS } from './model.js';

export const ABOUT =
  'The same sphere under the same sky, lit five ways. The first image solves the reflectance equation over all ' +
  'incoming light (the sky and the sun’s disc) by Monte Carlo: the general illumination model, what a path ' +
  'tracer would converge to. The others are what real-time renderers do instead: prefilter the whole sky into an ' +
  'environment map (image-based lighting), or keep the sun apart as an area light or as a punctual light and ' +
  'prefilter only the sky, or replace everything by one ambient colour. The table gives what each costs on this ' +
  'GPU and how far it lands from the reference. Try a smooth metal (gold, α 0.05) and a rough dielectric. The ' +
  'sun is enlarged: a disc of 2° radius, 7.5 times the real sun’s 0.27° (56 times its solid angle), so that the ' +
  '256 × 128 map (1.4° texels) resolves it. A real-sized sun would make the punctual light nearly exact except on ' +
  'near-mirrors, and the map would smear it over a whole texel.';

export const TERMS_USED = [
  'dfgTableUv',
  'sphereLightRepresentativeDir',
  'sphereLightNormalization',
  'sphereLightCLight',
  'sampleCone',
];

/** Where each model fails, by its key (model.js's MODELS). */
export const FAILS = {
  ibl:
    'The sun is one more bright patch of a prefiltered map: its highlight is blurred by the map’s resolution and ' +
    'the prefilter assumes n = v = r, wrong at grazing angles.',
  area:
    'The representative point reshapes the highlight for the sun’s size, with an energy factor that is only ' +
    'approximate; the sky is still prefiltered.',
  punctual: 'The sun has no size: on smooth surfaces its highlight is a needle far too bright and far too small.',
  ambient: 'No direction at all: no shading from the sun, no sky-to-ground gradient, no reflections.',
};

const fmt = (x, digits = 3) => (Number.isFinite(x) ? x.toPrecision(digits) : '—');

/** The table of the models' costs and errors against the reference (`samples` of it so far). */
export function tableHtml(st, results, samples, resolution) {
  const converging = samples < Number(st.refSamples) ? ', still converging' : '';
  const caption =
    'Sun enlarged to 2° (the real one is 0.27°). ' +
    `Against the reference (${samples} of ${st.refSamples} samples per pixel${converging})`;
  const head = ['Illumination model', `GPU time (${resolution}² px)`, 'RMS error', 'relative', 'Where it fails'];
  // each cell names its column (data-label): on a phone the rows reflow into blocks that show those names
  const cell = (i, text) => `<td data-label="${head[i]}">${text}</td>`;
  const row = (r) =>
    `<tr><th scope="row">${r.name}</th>${cell(1, `${fmt(r.ms)} ms`)}${cell(2, fmt(r.rms))}` +
    `${cell(3, `${fmt(r.relative * 100)} %`)}${cell(4, r.fails)}</tr>`;
  return `<table class="data-table compact models-table"><caption>${caption}</caption>
      <thead><tr>${head.map((h) => `<th>${h}</th>`).join('')}</tr></thead><tbody>
      ${results.map(row).join('')}
      </tbody></table>`;
}

/** What the canvas shows, for a screen reader. */
export function description(st, results, samples) {
  const material = st.material === 'manual' ? `F0 ${st.f0}, diffuse ${st.cdiff}` : st.material;
  const errors =
    samples < Number(st.refSamples)
      ? 'The reference is still converging.'
      : `Relative RMS errors: ${results.map((r) => `${r.name} ${fmt(r.relative * 100)} %`).join(', ')}.`;
  return (
    `Lighting models: a sphere (${material}, roughness α ${st.alpha}) under a sky with a sun, by the reference and ` +
    `four illumination models. ${errors}`
  );
}

const GENERAL =
  'L_o(\\mathbf{v}) = \\int_{\\Omega} f(\\mathbf{l},\\mathbf{v}) \\otimes L_i(\\mathbf{l})\\nl \\,d\\omega_i';

/** The BRDF every image shares, the reference's integral and the punctual sun that replaces its disc. */
export const FORMULA = declareFormula('lighting-models', (state) => {
  const keys = { alpha: 'alpha', f0: state.material === 'manual' ? 'f0' : 'material' };
  const f = brdfTex(TERMS, materialOf(state), keys);
  const lines = [f, `${GENERAL}\\quad\\text{(reference)}`, `${PUNCTUAL}\\quad\\text{(the sun as a point)}`];
  return `\\begin{gathered}${lines.join('\\\\ ')}\\end{gathered}`;
});
