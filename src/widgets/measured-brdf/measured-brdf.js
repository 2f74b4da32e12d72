// measured-brdf: a measured BRDF (a MERL file dropped or picked, or a synthetic example) beside the talk's
// models: its lobe in the plane of incidence per channel with a fit overlaid, spheres under a punctual light
// (3-D textures on the GPU), its (θh, θd) image, the NDF it implies against the five fits, and the fits
// themselves with their residuals. Parsing and fitting run in a worker (src/measured/fit-worker.js).
import { createWidgetShell } from '../../core/widget-shell.js';
import { createPlot } from '../../core/plot.js';
import { seriesStyle } from '../../core/palettes.js';
import { lightDirFromAngles } from '../../core/light-control.js';
import { FIT_MODELS } from '../../measured/fit.js';
import { measuredFromTable } from '../../measured/merl.js';
import { createHalfDiffImage } from '../brdf-lobe/half-diff-image.js';
import { schema } from './schema.js';
import {
  EXAMPLES, THETA_H_DEG, VIEW_ANGLES, fitBRDF, fittedNdfSlice, lobeStateForFit, measuredNdfSlice, ndfStateForFit, planeOfIncidence,
  RESIDUAL_TOP, residualImage,
} from './model.js';
import { createFitClient } from './fit-client.js';
import { createMeasuredSpheres } from './spheres.js';
import { MERL_TEXTURE_BYTES } from './texture-size.js';
import { createDropZone, createFitTable } from './views.js';

export { schema };
const MODELS = Object.keys(FIT_MODELS);
const DEG = Math.PI / 180;
const CHANNELS = [['R', '#c0392b'], ['G', '#1e8449'], ['B', '#2e5cb8']];
const MB = (bytes) => `${(bytes / 1e6).toFixed(1)} MB`;

const ABOUT =
  'Drop a file from the MERL BRDF database (Matusik et al. 2003; not shipped here) or keep a synthetic example. ' +
  'The five models of the talk are fitted to it in the background, each with Schlick Fresnel and a Lambert ' +
  'diffuse per colour channel. The log plot of the NDF slice shows whether a model’s tail follows the data: ' +
  'on real materials GGX, ABC and shifted gamma keep up where Beckmann and Blinn-Phong fall away (Löw et al. ' +
  `2012, Bagher et al. 2012). Each table is a 3-D texture of ${MB(MERL_TEXTURE_BYTES)} on the GPU.`;

const TERMS_USED = ['fresnelSchlick', 'ndfGGX', 'ndfBeckmann', 'ndfBlinnPhong', 'ndfABC', 'ndfSGD', 'visibilitySmithGGXCorrelated', 'visibilitySmithBeckmannSeparable', 'visibilityCookTorrance'];

const logRange = (arrays) => {
  const all = arrays.flat().filter((x) => x > 0);
  const max = all.length ? Math.max(...all) : 1;
  return { min: max * 1e-4, max: max * 2, log: true };
};
const positive = (values) => values.map((x) => (x > 0 ? x : null));

function lobeSpec(measured, fit, lightDeg) {
  const m = measured ? planeOfIncidence(measured.lookup, lightDeg) : [[], [], []];
  const f = fit ? planeOfIncidence(fitBRDF(fit), lightDeg) : null;
  const series = [...CHANNELS.map(([c, stroke]) => ({ label: `measured ${c}`, stroke })),
    ...(f ? CHANNELS.map(([c, stroke]) => ({ label: `${FIT_MODELS[fit.model].label} fit ${c}`, stroke, dash: [6, 4] })) : [])];
  const data = [...m, ...(f ?? [])].map((s) => positive(Array.from(VIEW_ANGLES, (_, i) => s[i])));
  return {
    title: `f in the plane of incidence, light at ${lightDeg}° (log scale; dashed: fit)`, xLabel: 'View angle θv (degrees; + on the mirror side)', yLabel: 'f (1/sr)',
    x: { min: -90, max: 90 }, y: logRange([...m, ...(f ?? [])]), xValues: (u, t) => t.map((v) => `${v}°`), legend: true,
    series, data: [VIEW_ANGLES, ...data], filename: 'measured-lobe', height: 280,
  };
}

function ndfSpec(measured, fits) {
  const keys = MODELS.filter((k) => fits[k]);
  const best = Object.values(fits).sort((a, b) => a.error - b.error)[0];
  const label = best ? `measured θd = 0 slice, less the ${FIT_MODELS[best.model].label} fit’s diffuse, ÷ its V` : 'measured θd = 0 slice';
  const series = [{ label, stroke: '#000000', width: 2.5 }, ...keys.map((k) => ({ label: `${FIT_MODELS[k].label} fit`, ...seriesStyle(MODELS.indexOf(k)) }))];
  const data = [measured ? measuredNdfSlice(measured.table, best) : THETA_H_DEG.map(() => null), ...keys.map((k) => fittedNdfSlice(fits[k]))];
  return {
    title: 'The NDF the measurement implies, and the fits’ D / D(0) (log scale): the tails', xLabel: 'θh (degrees)', yLabel: 'relative to the peak',
    x: { min: 0, max: 90 }, y: { min: 1e-5, max: 2, log: true }, xValues: (u, t) => t.map((v) => `${v}°`), legend: true,
    series, data: [THETA_H_DEG, ...data.map((d) => d.map((x) => (x > 1e-5 ? x : null)))], filename: 'measured-ndf', height: 280,
  };
}

/** The widget's views, top to bottom: drop zone; lobe and spheres; (θh, θd) image and NDF slice; fits; residuals. */
function createViews(shell, state, { onFile, onLoadFit }) {
  const drop = createDropZone(shell.view, onFile);
  const rows = ['lobe-row', 'lobe-row', 'half-diff-row measured-residuals'].map((className) => Object.assign(document.createElement('div'), { className }));
  const lobePlot = createPlot(rows[0], lobeSpec(null, null, state.lightTheta));
  const sphereHolder = Object.assign(document.createElement('div'), { className: 'measured-spheres' });
  rows[0].append(sphereHolder);
  const spheres = createMeasuredSpheres(sphereHolder, { label: 'Spheres: the measured BRDF (left) and the overlaid fit (right)' });
  const imageHolder = Object.assign(document.createElement('div'), { className: 'half-diff-row' });
  rows[1].append(imageHolder);
  const image = createHalfDiffImage(imageHolder, 'Measured (G) over (θh, θd)');
  const ndfPlot = createPlot(rows[1], ndfSpec(null, {}));
  shell.view.append(rows[0], rows[1]);
  const table = createFitTable(shell.view, onLoadFit);
  shell.view.append(rows[2]);
  const residuals = MODELS.map((k) => createHalfDiffImage(rows[2], `${FIT_MODELS[k].label}: |∛f_fit − ∛f_meas|`));
  return { drop, lobePlot, spheres, image, ndfPlot, table, residuals, all: [lobePlot, ndfPlot, image, ...residuals, spheres, table, drop] };
}

/** Hands a fit to another widget: in place when it is on this page (brdf-lobe on the BRDF page), else a new tab. */
function loadFitInto(fit, fits, target) {
  const lobe = globalThis.__shadingLab?.widgets?.lobe;
  if (target === 'lobe' && lobe) {
    lobe.update(lobeStateForFit(fit));
    document.querySelector('[data-widget="brdf-lobe"]')?.scrollIntoView({ behavior: 'smooth' });
    return;
  }
  const [page, prefix, state] = target === 'lobe' ? ['brdf.html', 'lobe', lobeStateForFit(fit)] : ['ndf.html', 'ndf', ndfStateForFit(fit, fits)];
  const params = new URLSearchParams(Object.entries(state).map(([k, v]) => [`${prefix}.${k}`, typeof v === 'number' ? +v.toPrecision(4) : v]));
  window.open(`${page}?${params}`, '_blank', 'noopener');
}

const fitStatus = (fits, started) => {
  const done = Object.keys(fits).length;
  const running = done < MODELS.length ? MODELS[done] : null;
  const statusText = running ? `fitting ${FIT_MODELS[running].label} (${done} of 5 done)…` : `5 fits in ${((performance.now() - started) / 1000).toFixed(1)} s`;
  return { done, running, statusText };
};

export function createMeasuredBrdf(container, initialState = {}, { onStateChange } = {}) {
  const shell = createWidgetShell(container, { name: 'measured-brdf', schema, initialState, about: ABOUT, terms: TERMS_USED });
  const s = () => shell.state;
  let client = createFitClient(); // the worker that holds the table shown; a new file gets a new worker
  let measured = null;
  let fits = {};
  let sourceWords = '';
  let generation = 0; // a newer table makes older fits and tabulations stale
  let disposed = false;
  let [requests, shown] = [0, 0]; // loads are numbered: one that ends after a later one has shown is dropped
  const views = createViews(shell, s(), { onFile: (file) => loadFile(file), onLoadFit: (model, target) => fits[model] && loadFitInto(fits[model], fits, target) });
  const { drop, lobePlot, spheres, image, ndfPlot, table, residuals } = views;

  const drawLobe = () => lobePlot.setData(lobeSpec(measured, fits[s().overlay], s().lightTheta));
  const drawImages = () => {
    if (!measured) return;
    image.draw((th, td) => measured.valueAt(th, td, s().phiD * DEG)[1], `green channel at φd ${s().phiD}°`);
    MODELS.forEach((k, i) => residuals[i].draw(fits[k] ? residualImage(measured, fits[k], s().phiD) : () => 0,
      fits[k] ? `residual of the ${FIT_MODELS[k].label} fit at φd ${s().phiD}° (green), one scale for all five` : 'not fitted yet', { max: RESIDUAL_TOP }));
  };
  const drawSpheres = () => spheres.setLight(lightDirFromAngles(s().sphereLight, 135), s().exposure);
  const describe = () => {
    const best = Object.values(fits).sort((a, b) => a.error - b.error)[0];
    shell.describe(`${sourceWords}: ${Object.keys(fits).length} of 5 models fitted${best ? `; best: ${FIT_MODELS[best.model].label}, error ${best.error.toExponential(2)}` : ''}.`, spheres.canvas);
  };
  const tabulateOverlay = () => {
    const [gen, fit] = [generation, fits[s().overlay]];
    if (!fit) return spheres.setTable(1, null, '');
    client.tabulate(fit.model, fit.params).then((r) => {
      if (gen === generation && fits[s().overlay] === fit) spheres.setTable(1, r.half, `${FIT_MODELS[fit.model].label} fit`);
    }).catch((e) => gen === generation && shell.notices.show(e.message));
  };
  const onFitMessage = (gen, started) => (msg) => {
    if (gen !== generation) return;
    if (msg.type === 'fitted') {
      fits = { ...fits, [msg.result.model]: msg.result };
      ndfPlot.setData(ndfSpec(measured, fits));
      if (msg.result.model === s().overlay) {
        drawLobe();
        tabulateOverlay();
      }
      drawImages();
      describe();
    }
    const { done, running, statusText } = fitStatus(fits, started);
    const partial = msg.type === 'progress' ? Math.min(msg.evaluations / 150, 0.95) : 0;
    table.draw(fits, { running, progressValue: (done + partial) / MODELS.length, statusText });
  };
  const runFits = () => {
    const gen = generation;
    table.draw(fits, { running: MODELS[0], progressValue: 0, statusText: 'fitting in the background…' });
    client.fit(MODELS, {}, onFitMessage(gen, performance.now())).catch((e) => gen === generation && shell.notices.show(e.message));
  };

  /** Reads a table in a new worker; only if it parses does it replace what is shown (and the old worker). */
  const load = (request, words, failure) => {
    const next = createFitClient();
    const ticket = ++requests;
    request(next).then((result) => {
      if (disposed || ticket < shown) return next.dispose();
      shown = ticket;
      client.dispose();
      client = next;
      generation++;
      measured = measuredFromTable(result.table);
      fits = {};
      sourceWords = words;
      drop.setSource(`${words}. Read in ${result.ms.toFixed(0)} ms in a worker; ${(result.missing / 3).toLocaleString('en')} of 1,458,000 nodes per channel missing (below the horizon or not measured).`);
      spheres.setTable(0, result.half, 'measured');
      spheres.setTable(1, null, '');
      drawLobe();
      ndfPlot.setData(ndfSpec(measured, fits));
      drawImages();
      describe();
      runFits();
    }).catch((e) => {
      next.dispose();
      shell.notices.show(failure(e));
    });
  };
  const loadExample = (key) => {
    const e = EXAMPLES[key];
    load((c) => c.synthesize(e.model, e.params), e.label, (err) => err.message);
  };
  const loadFile = (file) => load((c) => file.arrayBuffer().then((b) => c.parse(b)), `${file.name} (a MERL file you loaded)`,
    (e) => `${file.name}: ${e.message} The BRDF shown before is kept.`);

  const onChanged = (changed) => {
    if (changed.includes('example')) loadExample(s().example);
    if (changed.some((k) => ['lightTheta', 'overlay'].includes(k))) drawLobe();
    if (changed.includes('overlay')) tabulateOverlay();
    if (changed.includes('phiD')) drawImages();
    if (changed.some((k) => ['sphereLight', 'exposure'].includes(k))) drawSpheres();
  };
  const update = shell.connect({ title: 'Measured BRDF', onChanged, onStateChange });
  drawSpheres();
  table.draw(fits, { progressValue: 0, statusText: 'making the synthetic example…' });
  loadExample(s().example);

  return {
    update,
    getState: () => shell.state,
    getFits: () => fits,
    dispose() {
      disposed = true;
      generation++;
      client.dispose();
      views.all.forEach((x) => x.dispose());
      shell.dispose();
    },
  };
}

export const widget = { name: 'measured-brdf', schema, create: createMeasuredBrdf };
