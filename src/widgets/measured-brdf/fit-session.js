// The measured-BRDF widget's work in the fit worker (src/measured/fit-worker.js): reading a table (a dropped
// file or a synthetic example), fitting the five models to it, tabulating the overlaid fit for the spheres.
// ctx: { shell, views, paint, data }; data.client is the worker that holds the table shown (a new table gets a
// new worker), data.generation makes older fits and tabulations stale when a newer table shows.
import { FIT_MODELS } from '../../measured/fit.js';
import { MERL_BYTES, measuredFromTable } from '../../measured/merl.js';
import { createFitClient } from './fit-client.js';
import { EXAMPLES } from './model.js';
import { EXAMPLE_FITS } from './example-fits.data.js';
import { fitStatusWords, shippedFitsWords, tableReadWords, tooLargeWords } from './words.js';

const MODELS = Object.keys(FIT_MODELS);

const fitStatus = (fits, started) => {
  const done = Object.keys(fits).length;
  const running = done < MODELS.length ? MODELS[done] : null;
  return { done, running, statusText: fitStatusWords(done, running, (performance.now() - started) / 1000) };
};

/** Tabulates the overlaid fit in the worker and puts it on the second sphere (if still current when done). */
export function tabulateOverlay({ shell, views, data }) {
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

/**
 * A table the worker read (with the worker that holds it) replaces the one shown, with its fits: those of an example
 * were made ahead (`fits`, scripts/example-fits.js: the same fitter on the same table); any other table is fitted
 * in the worker.
 */
function showTable(ctx, next, result, { words, name, fits }) {
  const { views, paint, data } = ctx;
  data.client?.dispose();
  Object.assign(data, {
    client: next,
    tabulated: null,
    generation: data.generation + 1,
    measured: measuredFromTable(result.table),
    fits: { ...fits },
    sourceWords: words,
    sourceName: name,
  });
  views.drop.setSource(tableReadWords(words, result));
  views.spheres.setTable(0, result.half, 'measured');
  views.spheres.setTable(1, null, '');
  ['lobe', 'ndf', 'images', 'describe'].forEach((k) => paint[k]());
  if (!fits) return runFits(ctx);
  tabulateOverlay(ctx);
  views.table.draw(data.fits, { progressValue: 1, statusText: shippedFitsWords });
}

/**
 * `loadExample(key)` and `loadFile(file)`: each reads its table in a new worker; only if it parses does it
 * replace what is shown (and the old worker). Loads are numbered: one that ends after a later one has shown is
 * dropped.
 */
export function createTableLoader(ctx) {
  const { shell, data } = ctx;
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
  return {
    loadExample(key) {
      const e = EXAMPLES[key];
      load(
        (c) => c.synthesize(e.model, e.params),
        { words: e.label, name: `synthetic ${e.model.toUpperCase()} example (writeMerl)`, fits: EXAMPLE_FITS[key] },
        (err) => err.message,
      );
    },
    loadFile(file) {
      // refused by size before a byte is read: a 4 GB drop would otherwise be read whole and copied to the worker
      if (file.size > MERL_BYTES) return void shell.notices.show(tooLargeWords(file, MERL_BYTES));
      load(
        (c) => file.arrayBuffer().then((b) => c.parse(b)),
        { words: `${file.name} (a MERL file you loaded)`, name: file.name },
        (e) => `${file.name}: ${e.message} The BRDF shown before is kept.`,
      );
    },
  };
}
