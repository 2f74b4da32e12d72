// anisotropic-microsurface (beyond the talk): a 3-D Gaussian random surface with a different roughness along t and
// b, its picture lit from one direction with the shadows ray-traced, and G1 ray-traced at thirteen azimuths against
// Smith's anisotropic G1. The ray-traced figures (the table, the description, the sweep) and the whole surface (every
// other point of it while a control moves) follow once a drag pauses.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createSettledTask } from '../../core/framework/render-loop.js';
import { createPlot } from '../../core/ui/plot.js';
import { SURFACE_KEYS, SWEEP_KEYS, TERMS_USED, schema } from './schema.js';
import { createSurface, measuredAt, smithAt } from './model.js';
import { ABOUT, TITLE, describeSurface, statsHtml } from './words.js';
import { drawSurface } from './surface-view.js';
import { createAzimuthSweep } from './sweep.js';
import { azimuthPlotSpec } from './plot.js';

export { schema };

const DRAG_EVERY = 2; // a new surface is first built at every other point (model.js): a quarter of the work

/** The figures at the state's light direction that the table and the description give. */
const figuresAt = (state, surface) => ({
  measured: measuredAt(surface, state.theta, state.phi),
  smith: smithAt(surface, state.theta, state.phi),
});

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const canvas = document.createElement('canvas');
  canvas.className = 'aniso-microsurface';
  const stats = document.createElement('div');
  shell.view.append(canvas, stats);

  let surface = null; // { field, maxima, alphas, sweep }
  let plot = null;
  let shadowShare = 0;
  const spec = () => azimuthPlotSpec(shell.state, surface, surface.sweep.data);
  const rebuild = (newSurface, every = 1) => {
    surface?.sweep.cancel();
    const next = newSurface ? createSurface(shell.state, every) : surface;
    next.sweep = createAzimuthSweep(next, shell.state.theta, () => plot?.setData(spec()));
    surface = next;
  };
  const figuresLater = createSettledTask(() => {
    if (surface.every > 1) {
      rebuild(true); // the whole surface, once the drag pauses
      plot?.setData(spec());
    }
    shadowShare = drawSurface(canvas, shell.state, surface, 'fine');
    const figures = figuresAt(shell.state, surface);
    stats.innerHTML = statsHtml(shell.state, surface, figures);
    shell.describe(describeSurface(shell.state, figures, shadowShare), canvas);
    surface.sweep.start();
  });
  const render = (newSurface, newSweep = newSurface) => {
    if (newSweep) rebuild(newSurface, DRAG_EVERY); // a new surface: every other point of it until the drag pauses
    drawSurface(canvas, shell.state, surface, 'coarse'); // the full picture follows once the drag pauses
    figuresLater.schedule();
    if (!newSweep) return;
    if (plot) plot.setData(spec());
    else plot = createPlot(shell.view, spec());
  };
  render(true);
  const resize = new ResizeObserver(() => drawSurface(canvas, shell.state, surface));
  resize.observe(canvas);

  const onChanged = (changed) =>
    render(
      changed.some((k) => SURFACE_KEYS.includes(k)),
      changed.some((k) => SWEEP_KEYS.includes(k)),
    );
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    /** Ray-traced G1 at the measured azimuths and Smith's there, for tests. */
    getG1: () => {
      figuresLater.flush();
      const { azimuths, measured, away, complete } = surface.sweep.data;
      const smith = azimuths.map((p) => smithAt(surface, shell.state.theta, p));
      return { complete, azimuths: [...azimuths], measured: [...measured], away: [...away], smith };
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

export const widget = { name: 'anisotropic-microsurface', schema, create, terms: TERMS_USED };
