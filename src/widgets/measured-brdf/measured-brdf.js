// measured-brdf: a measured BRDF (a MERL file dropped or picked, or a synthetic example) beside the talk's
// models: its lobe in the plane of incidence per channel with a fit overlaid, spheres under a punctual light
// (3-D textures on the GPU), its (θh, θd) image, the NDF it implies against the five fits, and the fits
// themselves with their residuals. Parsing and fitting run in a worker (src/measured/fit-worker.js).
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { schema, TERMS_USED } from './schema.js';
import { ABOUT, TITLE } from './words.js';
import { createViews } from './layout.js';
import { createPainter } from './painter.js';
import { createTableLoader, tabulateOverlay } from './fit-session.js';
import { loadFitInto } from './hand-off.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'measured-brdf',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  // what the views show, and the bookkeeping of the worker that holds it (fit-session.js): none until the first
  // table is read (in a worker of its own), so that no worker is started only to be stopped while it loads
  const data = {
    client: null,
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
    onFile: (file) => tables.loadFile(file),
    onLoadFit: (model, target) => data.fits[model] && loadFitInto(data.fits[model], data, target),
  });
  const paint = createPainter(views, shell, () => data);
  const ctx = { shell, views, paint, data };
  const tables = createTableLoader(ctx);

  const onChanged = (changed) => {
    if (changed.includes('example')) tables.loadExample(shell.state.example);
    if (changed.some((k) => ['lightTheta', 'overlay'].includes(k))) paint.lobe();
    if (changed.includes('overlay')) {
      paint.ndf();
      tabulateOverlay(ctx);
    }
    if (changed.includes('phiD')) paint.images();
    if (changed.some((k) => ['sphereLight', 'exposure'].includes(k))) paint.spheres();
    paint.describe();
  };
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });
  ['spheres', 'images', 'describe'].forEach((k) => paint[k]());
  views.table.draw(data.fits, { progressValue: 0, statusText: 'making the synthetic example…' });
  tables.loadExample(shell.state.example);

  return {
    update,
    getState: () => shell.state,
    getFits: () => data.fits,
    /** The GPU view's steps done: the table read, the overlaid fit tabulated (later fits redraw 2-D plots only). */
    getProgress: () => ({ frame: (data.measured ? 1 : 0) + (data.tabulated ? 1 : 0), target: 2 }),
    dispose() {
      Object.assign(data, { disposed: true, generation: data.generation + 1 });
      data.client?.dispose();
      views.all.forEach((x) => x.dispose());
      shell.dispose();
    },
  };
}

export const widget = { name: 'measured-brdf', schema, create, terms: TERMS_USED };
