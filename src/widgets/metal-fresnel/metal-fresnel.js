// metal-fresnel: past the talk, a metal's Fresnel curve per channel from its measured (n, k), exact, beside
// Schlick, Gulbrandsen's edge tint and F82-tint (OpenPBR's metal), with their errors and a table of the worst
// errors over the talk's five metals.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { materialByKey } from '../../math/materials.js';
import { TERMS_USED, schema } from './schema.js';
import { angleGrid, compareMetal, errorTable } from './model.js';
import { errorSpec, reflectanceSpec } from './plots.js';
import { buildErrorTable } from './table-view.js';
import { ABOUT, TITLE, describeMetal, sourceLine } from './words.js';

export { schema };

export function create(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const plots = document.createElement('div');
  plots.className = 'plots';
  const source = document.createElement('p');
  source.className = 'source';
  const tableHolder = document.createElement('div');
  shell.view.append(plots, source, tableHolder);

  const angles = angleGrid();
  const rows = errorTable(angles); // the same for every state: computed once
  const specs = () => {
    const channels = compareMetal(shell.state.metal, angles);
    const name = materialByKey(shell.state.metal).name;
    return { channels, reflectance: reflectanceSpec(angles, channels, shell.state, name) };
  };
  let current = specs();
  const reflectance = createPlot(plots, current.reflectance);
  const error = createPlot(plots, errorSpec(angles, current.channels, shell.state));
  const show = () => {
    source.textContent = sourceLine(shell.state.metal);
    tableHolder.replaceChildren(...buildErrorTable(rows, shell.state.metal));
    shell.describe(describeMetal(shell.state, current.channels));
  };
  show();

  const refresh = () => {
    current = specs();
    reflectance.setData(current.reflectance);
    error.setData(errorSpec(angles, current.channels, shell.state));
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

export const widget = { name: 'metal-fresnel', schema, create, terms: TERMS_USED };
