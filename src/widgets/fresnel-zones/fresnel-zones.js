// fresnel-zones: the talk's live demo. A shape under a light the user drags; the glass Fresnel of n·v,
// the zones of n·v, the zones of l·h, and the l·h zones weighted by the rest of the BRDF, with the share
// of covered pixels (or of reflected light) in each zone summed on the GPU: after the frame, once a drag pauses
// (a GPU read-back that the picture need not wait for; the shares of the last state are exact).
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createViewport } from '../../core/framework/viewport.js';
import { createSettledTask } from '../../core/framework/render-loop.js';
import { schema, TERMS_USED } from './schema.js';
import { ABOUT, TITLE, describeView } from './words.js';
import { createZonesScene } from './scene-view.js';
import { NOT_MEASURED, createZoneStats } from './zone-stats.js';
import { createZoneLegend } from './legend.js';
import { attachViewTools } from './view-tools.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const getState = () => shell.state;
  const column = document.createElement('div');
  column.className = 'view-column';
  shell.view.append(column);

  const view = createZonesScene(getState);
  const legend = createZoneLegend();
  let stats = null; // the zone shares, measured on the GPU
  let tools = null; // light control, probe, save buttons
  const showMeasured = () => {
    const measured = stats?.measured ?? NOT_MEASURED;
    legend.show(shell.state, measured);
    shell.describe(describeView(shell.state, measured), viewport?.canvas);
  };
  const measureNow = () => {
    if (viewport.renderer.getContext().isContextLost()) return; // measured again on the next draw
    view.applyState();
    if (stats.measure(shell.state)) showMeasured();
  };
  const measureLater = createSettledTask(measureNow);
  const draw = (renderer) => {
    view.applyState();
    view.render(renderer);
    tools?.drawLight();
    measureLater.schedule();
  };
  const onResize = (w, h) => {
    view.fit(w, h);
    stats?.invalidate();
  };
  // multisampling only once a drag pauses: the meshes' silhouettes need it, a drag's frames cannot afford it
  const viewport = createViewport(column, { draw, onResize, label: 'Fresnel zones view', antialias: 'settled' });
  if (viewport) {
    stats = createZoneStats(viewport.renderer, view);
    const getZoneShares = () => (measureLater.flush(), stats.measured.zoneShares);
    tools = attachViewTools(viewport, column, { getState, update: (p) => update(p), view, getZoneShares });
  }
  column.append(legend.element);
  if (!viewport) showMeasured();

  const onChanged = (changed) => {
    if (changed.includes('shape')) view.setShape(shell.state.shape);
    stats?.invalidate(changed);
    if (changed.includes('palette')) showMeasured();
    // the probe reads its point again with the new light or material (a new shape or camera moves the point)
    if (!changed.includes('shape') && !changed.includes('camera')) tools?.refreshProbe();
    viewport?.invalidate();
  };
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState,
    /** Zone shares last measured on the GPU (for tests and exercises). */
    getZoneShares: () => (measureLater.flush(), [...(stats?.measured ?? NOT_MEASURED).zoneShares]),
    /** In the weighted mode: the shares averaged over light directions uniform on the sphere. */
    getAverageShares: () => (measureLater.flush(), stats?.measured.averageShares?.slice() ?? null),
    /** Number of distinct shader programs compiled so far, and the source of the one in use. */
    getProgramInfo: view.programInfo,
    dispose() {
      measureLater.cancel();
      tools?.dispose();
      stats?.dispose();
      view.dispose();
      viewport?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'fresnel-zones', schema, create, terms: TERMS_USED };
