// fresnel-curves: reflectance against angle of incidence for chosen materials, exact and Schlick
// overlaid, the talk's three zones shaded behind, and a second plot of Schlick's error.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { TERMS_USED, schema } from './schema.js';
import { buildSeries } from './model.js';
import { ABOUT, TITLE, describeCurves } from './words.js';
import { errorSpec, reflectanceSpec } from './plots.js';
import { renderReadout } from './readout.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const plots = document.createElement('div');
  plots.className = 'plots';
  const summary = document.createElement('div');
  summary.className = 'summary';
  shell.view.append(plots, summary);

  let data = buildSeries(shell.state);
  const onCursor = (index) => renderReadout(summary, data, index);
  const reflectance = createPlot(plots, reflectanceSpec(data, shell.state), { onCursor });
  const error = createPlot(plots, errorSpec(data), { onCursor });
  const show = () => {
    renderReadout(summary, data, null);
    shell.describe(describeCurves(data.curves));
  };
  show();

  const refresh = () => {
    data = buildSeries(shell.state);
    reflectance.setData(reflectanceSpec(data, shell.state));
    error.setData(errorSpec(data));
    show();
  };
  const update = shell.connect({ title: TITLE, onChanged: refresh, onStateChange });

  return {
    update,
    getState: () => shell.state,
    dispose() {
      reflectance.dispose();
      error.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'fresnel-curves', schema, create, terms: TERMS_USED };
