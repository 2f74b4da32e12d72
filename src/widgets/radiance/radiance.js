// radiance: the talk's "physics → math" step. A lamp seen from a distance the user sets: every pixel it covers
// shows the same radiance at any distance, while the irradiance it gives falls as 1/d². And a light spectrum
// and a surface's reflectance reduced to RGB: the per-wavelength product against the renderer's RGB ⊗ RGB.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { TERMS_USED, schema } from './schema.js';
import { colours, lampView } from './model.js';
import { ABOUT, TITLE, describeRadiance } from './words.js';
import { lampTableHtml, rgbTableHtml } from './tables.js';
import { drawLamp } from './lamp-view.js';
import { lampPlotSpec, spectrumPlotSpec } from './plots.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const canvas = document.createElement('canvas');
  canvas.className = 'radiance-lamp';
  const lampTable = document.createElement('div');
  const rgbTable = document.createElement('div');
  shell.view.append(canvas);
  const lampPlot = createPlot(shell.view, lampPlotSpec(shell.state));
  shell.view.append(lampTable);
  const spectrumPlot = createPlot(shell.view, spectrumPlotSpec(shell.state));
  shell.view.append(rgbTable);

  const render = (changed) => {
    const s = shell.state;
    const view = lampView(s);
    const touched = (...keys) => !changed || changed.some((k) => keys.includes(k));
    if (touched('distance', 'lampRadius')) lampPlot.setData(lampPlotSpec(s));
    if (touched('light', 'surface')) spectrumPlot.setData(spectrumPlotSpec(s));
    drawLamp(canvas, s, view);
    lampTable.innerHTML = lampTableHtml(s, view);
    const c = colours(s.light, s.surface);
    rgbTable.innerHTML = rgbTableHtml(c);
    shell.describe(describeRadiance(s, view, c), canvas);
  };
  render(null);
  const resize = new ResizeObserver(() => drawLamp(canvas, shell.state, lampView(shell.state)));
  resize.observe(canvas);
  const update = shell.connect({ title: TITLE, onChanged: render, onStateChange });

  return {
    update,
    getState: () => shell.state,
    dispose() {
      resize.disconnect();
      lampPlot.dispose();
      spectrumPlot.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'radiance', schema, create, terms: TERMS_USED };
