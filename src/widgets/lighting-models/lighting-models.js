// lighting-models: the talk's ladder of illumination models on one material under one sky with a sun. General
// lighting (the reference: Monte Carlo over the sky and the sun's disc), then image-based lighting (the whole sky,
// sun included, by the split sum), an area light (the sun as a sphere light), a punctual light (the sun as a
// point) and ambient light (one constant for everything), each with its GPU time and its error.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { REFERENCE_BATCH } from '../../lab/lab-renderer.js';
import { materialOf } from '../../lab/lab-scene.js';
import { createLabView } from '../../lab/lab-view.js';
import { METHODS, MODELS, TERMS, sky, sunSphere } from './model.js';
import { schema } from './schema.js';
import { ABOUT, TERMS_USED, description, tableHtml } from './words.js';
import { sampleTarget } from '../../core/framework/debug-hooks.js';

export { MODELS, schema };

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
  table.tabIndex = 0; // a scrolling region is reachable by keyboard (narrower than its table, it scrolls)
  table.setAttribute('role', 'region');
  table.setAttribute('aria-label', 'Each illumination model: its cost and its error against the reference');
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
    if (lab.batches * REFERENCE_BATCH < sampleTarget(Number(st.refSamples))) {
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
  view.setPanels(MODELS.length + 1);
  shell.view.append(table);
  const onChanged = () => view.setDisplay({ exposure: shell.state.exposure, errorScale: shell.state.errorScale });
  const update = shell.connect({ title: 'Lighting models', onChanged, onStateChange });
  onChanged();

  return {
    update,
    getState: () => shell.state,
    getResults: () => results.map(({ key, name, rms, relative, ms }) => ({ key, name, rms, relative, ms })),
    getProgress: () => ({ frame: samples, target: sampleTarget(Number(shell.state.refSamples)) }),
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
