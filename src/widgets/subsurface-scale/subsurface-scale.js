// subsurface-scale: light entering a scattering material at one point comes back out at some distance.
// Random walks in a 2-D slab show where; a histogram gives how far; a shading-sample circle the user resizes
// shows when that distance can be ignored (the pixel is large: diffuse shading is local) and when not.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { schema, TERMS_USED } from './schema.js';
import { isLocal, statistics, unitWalks } from './model.js';
import { ABOUT, TITLE, describeWalks, statisticsTable, verdictWords } from './words.js';
import { drawWalks } from './walks-view.js';
import { createExitPlot } from './exit-plot.js';

export { schema };
const STATISTICS_KEYS = ['sigmaS', 'sigmaA', 'seed', 'pixel'];

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'subsurface-scale',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const canvas = Object.assign(document.createElement('canvas'), { className: 'subsurface' });
  const verdict = Object.assign(document.createElement('p'), { className: 'verdict' });
  const plotHolder = document.createElement('div');
  const table = document.createElement('div');
  shell.view.append(canvas, verdict, plotHolder, table);
  let walks = unitWalks(shell.state.seed); // σs and σa scale and weight them: a new seed alone walks again
  let stats = statistics(shell.state, walks);
  const plot = createExitPlot(plotHolder, shell.state, stats);

  const draw = () => drawWalks(canvas, shell.state, stats);
  const show = () => {
    draw();
    verdict.className = `verdict ${isLocal(stats) ? 'ok' : 'warn'}`;
    verdict.textContent = verdictWords(stats);
    shell.describe(describeWalks(shell.state, stats), canvas);
    table.innerHTML = statisticsTable(shell.state, stats);
  };
  const onChanged = (changed) => {
    if (changed.includes('seed')) walks = unitWalks(shell.state.seed);
    if (changed.some((k) => STATISTICS_KEYS.includes(k))) {
      stats = statistics(shell.state, walks);
      plot.show(shell.state, stats);
    }
    show();
  };
  show();
  const resize = new ResizeObserver(draw);
  resize.observe(canvas);
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getStatistics: () => ({
      reflectance: stats.reflectance,
      insideShare: stats.insideShare,
      median: stats.median,
      mean: stats.mean,
    }),
    dispose() {
      resize.disconnect();
      plot.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'subsurface-scale', schema, create, terms: TERMS_USED };
