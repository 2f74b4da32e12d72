// lighting-models: the talk's ladder of illumination models on one material under one sky with a sun. General
// lighting (the reference: Monte Carlo over the sky and the sun's disc), then image-based lighting (the whole sky,
// sun included, by the split sum), an area light (the sun as a sphere light), a punctual light (the sun as a
// point) and ambient light (one constant for everything), each with its GPU time and its error.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { REFERENCE_BATCH } from '../../lab/lab-renderer.js';
import { MATERIAL_FIELDS, materialOf } from '../../lab/lab-scene.js';
import { createLabView } from '../../lab/lab-view.js';
import { SUN, skyPixels } from '../../lab/environments.js';
import { sphereLightCLight } from '../../math/lighting.js';

export const schema = {
  ...MATERIAL_FIELDS,
  // a dark, fairly smooth dielectric by default: the sun's highlight is where the models differ most
  diffuse: { ...MATERIAL_FIELDS.diffuse, default: '#2f4f7f' },
  alpha: { ...MATERIAL_FIELDS.alpha, default: 0.1 },
  show: { type: 'enum', options: { images: 'Images', errors: 'Error images' }, default: 'images', label: 'Show' },
  refSamples: {
    type: 'enum',
    options: { 128: '128', 512: '512', 2048: '2048' },
    default: '512',
    label: 'Reference samples / pixel',
  },
  exposure: { type: 'number', min: 0.1, max: 8, step: 0.05, default: 0.8, label: 'Exposure' },
  errorScale: { type: 'number', min: 0.005, max: 1, step: 0.005, default: 0.1, label: 'Error image: full scale' },
};

const sunCLight = SUN.radiance.map((L) => sphereLightCLight(L, SUN.sin));

/** The mean radiance of the sky, sun included, over the whole sphere: the one number ambient light keeps. */
function skyMean() {
  const { data, width, height } = skyPixels(256, 128, true);
  const sum = [0, 0, 0];
  let weight = 0;
  for (let j = 0; j < height; j++) {
    const w = Math.cos(((j + 0.5) / height - 0.5) * Math.PI);
    for (let i = 0; i < width; i++) for (let c = 0; c < 3; c++) sum[c] += data[(j * width + i) * 4 + c] * w;
    weight += w * width;
  }
  return sum.map((x) => x / weight);
}

const sky = { intensity: 1 };
const sunSphere = { dir: SUN.dir, sin: SUN.sin, radiance: SUN.radiance };
// each model: its lights, which map its sky is (with the sun painted in, or without), and where it fails
export const MODELS = [
  {
    key: 'ibl',
    name: 'Image-based',
    lights: { env: sky },
    map: 'sky',
    fails:
      'The sun is one more bright patch of a prefiltered map: its highlight is blurred by the map’s resolution and ' +
      'the prefilter assumes n = v = r, wrong at grazing angles.',
  },
  {
    key: 'area',
    name: 'Area light + IBL sky',
    lights: { env: sky, sphere: sunSphere },
    map: 'sky-no-sun',
    fails:
      'The representative point reshapes the highlight for the sun’s size, with an energy factor that is only ' +
      'approximate; the sky is still prefiltered.',
  },
  {
    key: 'punctual',
    name: 'Punctual light + IBL sky',
    lights: { env: sky, punctual: { dir: SUN.dir, cLight: sunCLight } },
    map: 'sky-no-sun',
    fails: 'The sun has no size: on smooth surfaces its highlight is a needle far too bright and far too small.',
  },
  {
    key: 'ambient',
    name: 'Ambient only',
    lights: { ambient: skyMean() },
    map: 'furnace',
    fails: 'No direction at all: no shading from the sun, no sky-to-ground gradient, no reflections.',
  },
];

const ABOUT =
  'The same sphere under the same sky, lit five ways. The first image solves the reflectance equation over all ' +
  'incoming light (the sky and the sun’s disc) by Monte Carlo: the general illumination model, what a path ' +
  'tracer would converge to. The others are what real-time renderers do instead: prefilter the whole sky into an ' +
  'environment map (image-based lighting), or keep the sun apart as an area light or as a punctual light and ' +
  'prefilter only the sky, or replace everything by one ambient colour. The table gives what each costs on this ' +
  'GPU and how far it lands from the reference. Try a smooth metal (gold, α 0.05) and a rough dielectric. The ' +
  'sun is enlarged: a disc of 2° radius, 7.5 times the real sun’s 0.27° (56 times its solid angle), so that the ' +
  '256 × 128 map (1.4° texels) resolves it. A real-sized sun would make the punctual light nearly exact except on ' +
  'near-mirrors, and the map would smear it over a whole texel.';

const TERMS_USED = [
  'dfgTableUv',
  'sphereLightRepresentativeDir',
  'sphereLightNormalization',
  'sphereLightCLight',
  'sampleCone',
];
const TERMS = { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', diffuse: 'lambert', layers: 'both' };
const METHODS = { env: 'split-sum', area: 'representative', samples: 1 };
const fmt = (x, digits = 3) => (Number.isFinite(x) ? x.toPrecision(digits) : '—');

/** The table of the models' costs and errors against the reference (`samples` of it so far). */
function tableHtml(st, results, samples, resolution) {
  const converging = samples < Number(st.refSamples) ? ', still converging' : '';
  const caption =
    'Sun enlarged to 2° (the real one is 0.27°). ' +
    `Against the reference (${samples} of ${st.refSamples} samples per pixel${converging})`;
  const head = ['Illumination model', `GPU time (${resolution}² px)`, 'RMS error', 'relative', 'Where it fails'];
  const row = (r) =>
    `<tr><th scope="row">${r.name}</th><td>${fmt(r.ms)} ms</td><td>${fmt(r.rms)}</td>` +
    `<td>${fmt(r.relative * 100)} %</td><td>${r.fails}</td></tr>`;
  return `<table class="data-table compact"><caption>${caption}</caption>
      <thead><tr>${head.map((h) => `<th>${h}</th>`).join('')}</tr></thead><tbody>
      ${results.map(row).join('')}
      </tbody></table>`;
}

/** What the canvas shows, for a screen reader. */
function description(st, results, samples) {
  const material = st.material === 'custom' ? `F0 ${st.f0}, diffuse ${st.diffuse}` : st.material;
  const errors =
    samples < Number(st.refSamples)
      ? 'The reference is still converging.'
      : `Relative RMS errors: ${results.map((r) => `${r.name} ${fmt(r.relative * 100)} %`).join(', ')}.`;
  return (
    `Lighting models: a sphere (${material}, roughness α ${st.alpha}) under a sky with a sun, by the reference and ` +
    `four illumination models. ${errors}`
  );
}

export function createLightingModels(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'lighting-models',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const table = document.createElement('div');
  table.className = 'lab-readout';
  let results = [];
  let samples = 0;
  let approxKey = '';
  let refKey = '';
  const costs = [];

  const frame = ({ lab, environment, again }) => {
    const st = shell.state;
    const material = materialOf(st);
    const scene = (lights, map) => ({ material, terms: TERMS, lights, methods: METHODS, maps: environment(map) });
    const key = JSON.stringify(material);
    if (key !== approxKey) {
      MODELS.forEach((m, slot) => (costs[slot] = lab.renderApprox(scene(m.lights, m.map), slot)));
      approxKey = key;
    }
    if (key !== refKey) {
      lab.resetReference();
      refKey = key;
    }
    if (lab.batches * REFERENCE_BATCH < Number(st.refSamples)) {
      lab.accumulate(scene({ env: sky, sphere: sunSphere }, 'sky-no-sun'));
      again();
    }
    samples = lab.batches * REFERENCE_BATCH;
    results = MODELS.map((m, slot) => ({ ...m, ...lab.error(slot), ms: costs[slot] }));
    showTable(st);
    const image = st.show === 'errors' ? 'error' : 'approx';
    return [
      { image: 'reference', caption: `General (reference)` },
      ...MODELS.map((m, slot) => ({ image, slot, caption: m.name })),
    ];
  };

  const showTable = (st) => {
    table.innerHTML = tableHtml(st, results, samples, view.resolution);
    shell.describe(description(st, results, samples), view.canvas);
  };

  const onReset = () => ([approxKey, refKey] = ['', '']);
  const view = createLabView(shell.view, {
    label: 'Lighting models',
    resolution: 160,
    slots: MODELS.length,
    frame,
    onReset,
  });
  view.setAspect(MODELS.length + 1);
  shell.view.append(table);
  const onChanged = () => view.setDisplay({ exposure: shell.state.exposure, errorScale: shell.state.errorScale });
  const update = shell.connect({ title: 'Lighting models', onChanged, onStateChange });
  onChanged();

  return {
    update,
    getState: () => shell.state,
    getResults: () => results.map(({ key, name, rms, relative, ms }) => ({ key, name, rms, relative, ms })),
    getProgress: () => ({ frame: samples, target: Number(shell.state.refSamples) }),
    get canvas() {
      return view.canvas;
    },
    dispose() {
      view.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'lighting-models', schema, create: createLightingModels, terms: TERMS_USED };
