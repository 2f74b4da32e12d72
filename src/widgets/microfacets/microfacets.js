// microfacets: a 2-D microsurface under a bundle of light rays. Which facets face along h (and so reflect
// the light to the eye), which are shadowed from the light or masked from the eye, which rays bounce twice;
// and the measured share of shadowed microfacets against Smith's G1. The ray-traced figures (the table, the
// description, the G1 sweep) follow once a drag pauses: the cut is drawn first.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createSettledTask } from '../../core/framework/render-loop.js';
import { createPlot } from '../../core/ui/plot.js';
import { DEG } from '../../math/angles.js';
import { measuredG1 } from '../../math/microsurface.js';
import { SURFACE_KEYS, TERMS_USED, schema } from './schema.js';
import { G1_OPTIONS, createSurface, dirOf, halfAngleDeg, smithG1 } from './model.js';
import { ABOUT, LEGEND_HTML, TITLE, describeCut } from './words.js';
import { statsHtml } from './stats-table.js';
import { drawSurface } from './surface-view.js';
import { createG1Sweep } from './g1-sweep.js';
import { g1PlotSpec } from './g1-plot.js';

export { schema };

/** The figures at the light's angle that the table and the description give. */
function figuresAt(state, surface, twice) {
  const theta = Math.abs(state.lightTheta) * DEG;
  return {
    measured: measuredG1(surface.profile, theta, G1_OPTIONS),
    smith: smithG1(state, Math.cos(theta)),
    twice,
    hDeg: halfAngleDeg(dirOf(state.lightTheta), dirOf(state.viewTheta)),
  };
}

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const canvas = document.createElement('canvas');
  canvas.className = 'microsurface';
  const legend = document.createElement('p');
  legend.className = 'micro-legend';
  legend.innerHTML = LEGEND_HTML;
  const stats = document.createElement('div');
  shell.view.append(canvas, legend, stats);

  let surface = null; // { profile, bounds, sweep }
  let plot = null;
  let twice = 0; // rays drawn that bounce twice
  const rebuild = () => {
    surface?.sweep.cancel();
    const next = createSurface(shell.state);
    next.sweep = createG1Sweep(next.profile, () => plot?.setData(g1PlotSpec(shell.state, next.sweep.data)));
    surface = next;
  };
  const figuresLater = createSettledTask(() => {
    const figures = figuresAt(shell.state, surface, twice);
    stats.innerHTML = statsHtml(shell.state, figures);
    shell.describe(describeCut(shell.state, figures), canvas);
    surface.sweep.start();
  });
  const render = (newSurface) => {
    if (newSurface) rebuild();
    twice = drawSurface(canvas, shell.state, surface);
    figuresLater.schedule();
    if (!newSurface) return;
    if (plot) plot.setData(g1PlotSpec(shell.state, surface.sweep.data));
    else plot = createPlot(shell.view, g1PlotSpec(shell.state, surface.sweep.data));
  };
  render(true);
  const resize = new ResizeObserver(() => drawSurface(canvas, shell.state, surface));
  resize.observe(canvas);

  const onChanged = (changed) => render(changed.some((k) => SURFACE_KEYS.includes(k)));
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    /** Ray-traced G1 at 0°, 5°, … 85° and Smith's, for tests. */
    getG1: () => {
      figuresLater.flush();
      const { angles, measured, complete } = surface.sweep.data;
      const smith = angles.map((d) => smithG1(shell.state, Math.cos(d * DEG)));
      return { complete, angles: [...angles], measured: [...measured], smith };
    },
    dispose() {
      figuresLater.cancel();
      surface.sweep.cancel();
      resize.disconnect();
      plot?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'microfacets', schema, create, terms: TERMS_USED };
