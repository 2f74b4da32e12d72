// measured-brdf: a measured BRDF (a MERL file dropped or picked, or a synthetic example) beside the talk's
// models: its lobe in the plane of incidence per channel with a fit overlaid, spheres under a punctual light
// (3-D textures on the GPU), its (θh, θd) image, the NDF it implies against the five fits, and the fits
// themselves with their residuals. Parsing and fitting run in a worker (src/measured/fit-worker.js).
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { seriesStyle } from '../../core/ui/palettes.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { FIT_MODELS } from '../../measured/fit.js';
import { MERL_BYTES, measuredFromTable } from '../../measured/merl.js';
import { createHalfDiffImage } from '../brdf-lobe/half-diff-image.js';
import { createLobeView } from '../brdf-lobe/lobe-view.js';
import { describeCanvas } from '../../core/framework/describe.js';
import { schema } from './schema.js';
import {
  bestFit,
  EXAMPLES,
  THETA_H_DEG,
  VIEW_ANGLES,
  fitBRDF,
  fittedNdfSlice,
  lobe3dSpec,
  lobeStateForFit,
  measuredNdfSlice,
  ndfStateForFit,
  planeOfIncidence,
  RESIDUAL_TOP,
  residualImage,
} from './model.js';
import { createFitClient } from './fit-client.js';
import { createMeasuredSpheres } from './spheres.js';
import { MERL_TEXTURE_BYTES } from './texture-size.js';
import { createDropZone, createFitTable } from './views.js';
import { DEG } from '../../math/angles.js';

export { schema };
const MODELS = Object.keys(FIT_MODELS);
const CHANNELS = [
  ['R', '#c0392b'],
  ['G', '#1e8449'],
  ['B', '#2e5cb8'],
];
const MB = (bytes) => `${(bytes / 1e6).toFixed(1)} MB`;

const ABOUT =
  'Drop a file from the MERL BRDF database (Matusik et al. 2003; not shipped here) or keep a synthetic example. ' +
  'It is drawn as a lobe in the plane of incidence, as a 3-D lobe (green channel; drag to orbit) and on spheres. ' +
  'The five models of the talk are fitted to it in the background, each with Schlick Fresnel and a Lambert ' +
  'diffuse per colour channel. The log plot of the NDF slice shows whether a model’s tail follows the data: ' +
  'on real materials GGX, ABC and shifted gamma keep up where Beckmann and Blinn-Phong fall away (Löw et al. ' +
  `2012, Bagher et al. 2012). Each table is a 3-D texture of ${MB(MERL_TEXTURE_BYTES)} on the GPU.`;

const TERMS_USED = [
  'fresnelSchlick',
  'ndfGGX',
  'ndfBeckmann',
  'ndfBlinnPhong',
  'ndfABC',
  'ndfSGD',
  'visibilitySmithGGXCorrelated',
  'visibilitySmithBeckmannSeparable',
  'visibilityCookTorrance',
  'merlCoordinates',
];

const logRange = (arrays) => {
  const all = arrays.flat().filter((x) => x > 0);
  const max = all.length ? Math.max(...all) : 1;
  return { min: max * 1e-4, max: max * 2, log: true };
};
const positive = (values) => values.map((x) => (x > 0 ? x : null));

function lobeSpec(measured, fit, lightDeg) {
  const m = measured ? planeOfIncidence(measured.lookup, lightDeg) : [[], [], []];
  const f = fit ? planeOfIncidence(fitBRDF(fit), lightDeg) : null;
  const series = [
    ...CHANNELS.map(([c, stroke]) => ({ label: `measured ${c}`, stroke })),
    ...(f
      ? CHANNELS.map(([c, stroke]) => ({ label: `${FIT_MODELS[fit.model].label} fit ${c}`, stroke, dash: [6, 4] }))
      : []),
  ];
  const data = [...m, ...(f ?? [])].map((s) => positive(Array.from(VIEW_ANGLES, (_, i) => s[i])));
  return {
    title: `f in the plane of incidence, light at ${lightDeg}° (log scale; dashed: fit)`,
    xLabel: 'View angle θv (degrees; + on the mirror side)',
    yLabel: 'f (1/sr)',
    x: { min: -90, max: 90 },
    y: logRange([...m, ...(f ?? [])]),
    xValues: (u, t) => t.map((v) => `${v}°`),
    legend: true,
    series,
    data: [VIEW_ANGLES, ...data],
    filename: 'measured-lobe',
    height: 280,
  };
}

function ndfSpec(measured, fits, overlay) {
  const keys = MODELS.filter((k) => fits[k]);
  const best = bestFit(fits);
  const label = best
    ? `measured θd = 0 slice, less the ${FIT_MODELS[best.model].label} fit’s diffuse, ÷ its V`
    : 'measured θd = 0 slice';
  const fitSeries = (k) => ({
    label: `${FIT_MODELS[k].label} fit`,
    ...seriesStyle(MODELS.indexOf(k)),
    width: k === overlay ? 3 : 1.5,
  });
  const series = [{ label, stroke: '#000000', width: 2.5 }, ...keys.map(fitSeries)];
  const data = [
    measured ? measuredNdfSlice(measured.table, best) : THETA_H_DEG.map(() => null),
    ...keys.map((k) => fittedNdfSlice(fits[k])),
  ];
  return {
    title:
      'The NDF the measurement implies, and the fits’ D / D(0) ' +
      `(log scale; thick: ${FIT_MODELS[overlay].label}, overlaid): the tails`,
    xLabel: 'θh (degrees)',
    yLabel: 'relative to the peak',
    x: { min: 0, max: 90 },
    y: { min: 1e-5, max: 2, log: true },
    xValues: (u, t) => t.map((v) => `${v}°`),
    legend: true,
    series,
    data: [THETA_H_DEG, ...data.map((d) => d.map((x) => (x > 1e-5 ? x : null)))],
    filename: 'measured-ndf',
    height: 280,
  };
}

/** The widget's views, top to bottom: drop zone; lobe and spheres; (θh, θd) image and NDF slice; fits; residuals. */
function createViews(shell, state, { onFile, onLoadFit }) {
  const drop = createDropZone(shell.view, onFile);
  const rows = ['lobe-row', 'lobe-row', 'half-diff-row measured-residuals'].map((className) =>
    Object.assign(document.createElement('div'), { className }),
  );
  const lobePlot = createPlot(rows[0], lobeSpec(null, null, state.lightTheta));
  const sphereHolder = Object.assign(document.createElement('div'), { className: 'measured-spheres' });
  rows[0].append(sphereHolder);
  const spheres = createMeasuredSpheres(sphereHolder, {
    label: 'Spheres: the measured BRDF (left) and the overlaid fit (right)',
  });
  const lobeHolder = Object.assign(document.createElement('div'), { className: 'lobe-3d' });
  sphereHolder.append(lobeHolder);
  const lobe3d = createLobeView(lobeHolder);
  describeCanvas(lobe3d.canvas, '3-D lobe of the measured table: no table yet (drop a file, or wait for the example).');
  const imageHolder = Object.assign(document.createElement('div'), { className: 'half-diff-row' });
  rows[1].append(imageHolder);
  const image = createHalfDiffImage(imageHolder, 'Measured (G) over (θh, θd)');
  const ndfPlot = createPlot(rows[1], ndfSpec(null, {}, state.overlay));
  shell.view.append(rows[0], rows[1]);
  const table = createFitTable(shell.view, onLoadFit);
  shell.view.append(rows[2]);
  const residuals = MODELS.map((k) => createHalfDiffImage(rows[2], `${FIT_MODELS[k].label}: |∛f_fit − ∛f_meas|`));
  return {
    drop,
    lobePlot,
    lobe3d,
    spheres,
    image,
    ndfPlot,
    table,
    residuals,
    all: [lobePlot, lobe3d, ndfPlot, image, ...residuals, spheres, table, drop],
  };
}

/** Draws the views from the state and the data ({ measured, fits, sourceWords }) they show. */
function createPainter({ lobePlot, lobe3d, spheres, image, ndfPlot, residuals }, shell, data) {
  const s = () => shell.state;
  const images = () => {
    const { measured, fits } = data();
    const at = `at φd ${s().phiD}°`;
    image.draw(
      measured ? (th, td) => measured.valueAt(th, td, s().phiD * DEG)[1] : () => 0,
      measured ? `green channel ${at}` : `no table yet (${at})`,
    );
    MODELS.forEach((k, i) =>
      residuals[i].draw(
        measured && fits[k] ? residualImage(measured, fits[k], s().phiD) : () => 0,
        fits[k]
          ? `residual of the ${FIT_MODELS[k].label} fit ${at} (green; between nodes it holds the table's ` +
              'interpolation error too), one scale for all five'
          : `not fitted yet (${at})`,
        { max: RESIDUAL_TOP },
      ),
    );
  };
  return {
    lobe() {
      const { measured, fits } = data();
      const fit = fits[s().overlay];
      lobePlot.setData(lobeSpec(measured, fit, s().lightTheta));
      if (!measured) return;
      const spec = lobe3dSpec(measured.lookup, fit ? fitBRDF(fit) : null, s().lightTheta, lobe3d.directions);
      const fitWords = fit ? ` and the ${FIT_MODELS[fit.model].label} fit (wireframe)` : '';
      lobe3d.update({
        ...spec,
        description:
          `3-D lobe of the measured table's green channel (solid)${fitWords}, light ${s().lightTheta}° ` +
          `from n; each direction's distance from the centre is f, scaled to ${spec.max.toPrecision(3)} /sr.`,
      });
    },
    ndf: () => ndfPlot.setData(ndfSpec(data().measured, data().fits, s().overlay)),
    images,
    spheres: () => spheres.setLight(lightDirFromAngles(s().sphereLight, 135), s().exposure),
    describe() {
      const { fits, sourceWords } = data();
      const best = bestFit(fits);
      const bestWords = best ? `; best: ${FIT_MODELS[best.model].label}, error ${best.error.toExponential(2)}` : '';
      const fitted = `${Object.keys(fits).length} of 5 models fitted${bestWords}`;
      shell.describe(
        `${sourceWords || 'No table yet'}: ${fitted}. ` +
          `Spheres: the measured table (left) and the ${FIT_MODELS[s().overlay].label} fit (right) ` +
          `under a light ${s().sphereLight}° from the view, exposure ${s().exposure}.`,
        spheres.canvas,
      );
    },
  };
}

/**
 * Hands a fit to another widget: in place when it is on this page (brdf-lobe on the BRDF page), else a new tab
 * (ndf-explorer gets the measured NDF slice and the source's name in its URL too).
 */
function loadFitInto(fit, { fits, measured, sourceName }, target) {
  const lobe = globalThis.__shadingLab?.widgets?.lobe;
  if (target === 'lobe' && lobe) {
    lobe.update(lobeStateForFit(fit));
    document.querySelector('[data-widget="brdf-lobe"]')?.scrollIntoView({ behavior: 'smooth' });
    return;
  }
  const [page, prefix, state] =
    target === 'lobe'
      ? ['brdf.html', 'lobe', lobeStateForFit(fit)]
      : ['ndf.html', 'ndf', ndfStateForFit(fit, fits, measured, sourceName)];
  const params = new URLSearchParams(
    Object.entries(state).map(([k, v]) => [`${prefix}.${k}`, typeof v === 'number' ? +v.toPrecision(4) : String(v)]),
  );
  window.open(`${page}?${params}`, '_blank', 'noopener');
}

const fitStatus = (fits, started) => {
  const done = Object.keys(fits).length;
  const running = done < MODELS.length ? MODELS[done] : null;
  const statusText = running
    ? `fitting ${FIT_MODELS[running].label} (${done} of 5 done)…`
    : `5 fits in ${((performance.now() - started) / 1000).toFixed(1)} s`;
  return { done, running, statusText };
};

/** Tabulates the overlaid fit in the worker and puts it on the second sphere (if still current when done). */
function tabulateOverlay({ shell, views, data }) {
  const [gen, fit] = [data.generation, data.fits[shell.state.overlay]];
  data.tabulated = null;
  if (!fit) return views.spheres.setTable(1, null, '');
  data.client
    .tabulate(fit.model, fit.params)
    .then((r) => {
      if (gen !== data.generation || data.fits[shell.state.overlay] !== fit) return;
      views.spheres.setTable(1, r.half, `${FIT_MODELS[fit.model].label} fit`);
      data.tabulated = fit;
    })
    .catch((e) => gen === data.generation && shell.notices.show(e.message));
}

/** Fits the five models in the worker; each result is drawn as it comes, the progress bar follows. */
function runFits(ctx) {
  const { shell, views, paint, data } = ctx;
  const [gen, started] = [data.generation, performance.now()];
  views.table.draw(data.fits, { running: MODELS[0], progressValue: 0, statusText: 'fitting in the background…' });
  const onMessage = (msg) => {
    if (gen !== data.generation) return;
    if (msg.type === 'fitted') {
      data.fits = { ...data.fits, [msg.result.model]: msg.result };
      paint.ndf();
      if (msg.result.model === shell.state.overlay) {
        paint.lobe();
        tabulateOverlay(ctx);
      }
      paint.images();
      paint.describe();
    }
    const { done, running, statusText } = fitStatus(data.fits, started);
    const partial = msg.type === 'progress' ? Math.min(msg.evaluations / 150, 0.95) : 0;
    views.table.draw(data.fits, { running, progressValue: (done + partial) / MODELS.length, statusText });
  };
  data.client.fit(MODELS, {}, onMessage).catch((e) => gen === data.generation && shell.notices.show(e.message));
}

/** A table the worker read (with the worker that holds it) replaces the one shown; fits start over. */
function showTable(ctx, next, result, { words, name }) {
  const { views, paint, data } = ctx;
  data.client.dispose();
  Object.assign(data, {
    client: next,
    tabulated: null,
    generation: data.generation + 1,
    measured: measuredFromTable(result.table),
    fits: {},
    sourceWords: words,
    sourceName: name,
  });
  views.drop.setSource(
    `${words}. Read in ${result.ms.toFixed(0)} ms in a worker; ${(result.missing / 3).toLocaleString('en')} ` +
      'of 1,458,000 nodes per channel missing (below the horizon or not measured).',
  );
  views.spheres.setTable(0, result.half, 'measured');
  views.spheres.setTable(1, null, '');
  ['lobe', 'ndf', 'images', 'describe'].forEach((k) => paint[k]());
  runFits(ctx);
}

export function createMeasuredBrdf(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'measured-brdf',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  // client: the worker that holds the table shown (a new file gets a new worker); generation: a newer table
  // makes older fits and tabulations stale; loads are numbered, and one that ends after a later one has shown
  // is dropped
  const data = {
    client: createFitClient(),
    measured: null,
    fits: {},
    tabulated: null,
    sourceWords: '',
    sourceName: '',
    generation: 0,
    requests: 0,
    shown: 0,
    disposed: false,
  };
  const views = createViews(shell, shell.state, {
    onFile: (file) => loadFile(file),
    onLoadFit: (model, target) => data.fits[model] && loadFitInto(data.fits[model], data, target),
  });
  const paint = createPainter(views, shell, () => data);
  const ctx = { shell, views, paint, data };

  /** Reads a table in a new worker; only if it parses does it replace what is shown (and the old worker). */
  const load = (request, source, failure) => {
    const next = createFitClient();
    const ticket = ++data.requests;
    request(next)
      .then((result) => {
        if (data.disposed || ticket < data.shown) return next.dispose();
        data.shown = ticket;
        showTable(ctx, next, result, source);
      })
      .catch((e) => {
        next.dispose();
        shell.notices.show(failure(e));
      });
  };
  const loadExample = (key) => {
    const e = EXAMPLES[key];
    load(
      (c) => c.synthesize(e.model, e.params),
      { words: e.label, name: `synthetic ${e.model.toUpperCase()} example (writeMerl)` },
      (err) => err.message,
    );
  };
  const loadFile = (file) => {
    // refused by size before a byte is read: a 4 GB drop would otherwise be read whole and copied to the worker
    if (file.size > MERL_BYTES) {
      const [size, limit] = [file.size, MERL_BYTES].map((n) => n.toLocaleString('en'));
      const why = `${size} bytes, more than a MERL file’s ${limit}`;
      return void shell.notices.show(`${file.name}: ${why}. The BRDF shown before is kept.`);
    }
    load(
      (c) => file.arrayBuffer().then((b) => c.parse(b)),
      { words: `${file.name} (a MERL file you loaded)`, name: file.name },
      (e) => `${file.name}: ${e.message} The BRDF shown before is kept.`,
    );
  };

  const onChanged = (changed) => {
    if (changed.includes('example')) loadExample(shell.state.example);
    if (changed.some((k) => ['lightTheta', 'overlay'].includes(k))) paint.lobe();
    if (changed.includes('overlay')) {
      paint.ndf();
      tabulateOverlay(ctx);
    }
    if (changed.includes('phiD')) paint.images();
    if (changed.some((k) => ['sphereLight', 'exposure'].includes(k))) paint.spheres();
    paint.describe();
  };
  const update = shell.connect({ title: 'Measured BRDF', onChanged, onStateChange });
  ['spheres', 'images', 'describe'].forEach((k) => paint[k]());
  views.table.draw(data.fits, { progressValue: 0, statusText: 'making the synthetic example…' });
  loadExample(shell.state.example);

  return {
    update,
    getState: () => shell.state,
    getFits: () => data.fits,
    /** The GPU view's steps done: the table read, the overlaid fit tabulated (later fits redraw 2-D plots only). */
    getProgress: () => ({ frame: (data.measured ? 1 : 0) + (data.tabulated ? 1 : 0), target: 2 }),
    dispose() {
      Object.assign(data, { disposed: true, generation: data.generation + 1 });
      data.client.dispose();
      views.all.forEach((x) => x.dispose());
      shell.dispose();
    },
  };
}

export const widget = { name: 'measured-brdf', schema, create: createMeasuredBrdf, terms: TERMS_USED };
