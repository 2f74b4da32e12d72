// f0-tables: the talk's two tables of normal-incidence reflectance, with swatches, the linear and sRGB
// columns as printed and the sRGB recomputed from the linear column, and links that load each material
// into the other Fresnel widgets.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { TERMS_USED, schema } from './schema.js';
import { TABLES } from './model.js';
import { ABOUT, TITLE, describeSelected, sourceText } from './words.js';
import { buildTable } from './table-view.js';

export { schema };

/** options.onPick(materialKey, targetWidget) -> true when the page handled it (no navigation). */
export function create(container, initialState = {}, { onStateChange, onPick, locked } = {}) {
  const shell = createWidgetShell(container, { ...widget, about: ABOUT, initialState, locked });
  const holder = document.createElement('div');
  holder.className = 'f0-tables';
  shell.view.append(holder);
  const source = document.createElement('p');
  source.className = 'source';
  source.textContent = sourceText();

  const render = () => {
    const onSelect = (key) => update({ selected: key });
    const focused = holder.contains(document.activeElement)
      ? document.activeElement.closest('tr')?.dataset.material
      : null;
    holder.replaceChildren(...TABLES.map((t) => buildTable(t, shell.state, { onPick, onSelect })), source);
    if (focused) holder.querySelector(`tr[data-material="${focused}"]`)?.focus(); // keep the keyboard's place
    shell.describe(describeSelected(shell.state.selected));
  };

  const update = shell.connect({ title: TITLE, onChanged: render, onStateChange });
  render();

  return {
    update,
    getState: () => shell.state,
    dispose: shell.dispose,
  };
}

export const widget = { name: 'f0-tables', schema, create, terms: TERMS_USED };
