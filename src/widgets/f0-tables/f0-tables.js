// f0-tables: the talk's two tables of normal-incidence reflectance, with swatches, the linear and sRGB
// columns as printed and the sRGB recomputed from the linear column, and links that load each material
// into the other Fresnel widgets.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { rgbToHex } from '../../core/ui/palettes.js';
import { linearToSrgb } from '../../math/color.js';
import { METALS, NON_METALS, TABLE_SOURCE, iorFromF0, measuredSource } from '../../math/index.js';

export const schema = {
  selected: {
    type: 'enum',
    options: Object.fromEntries([...METALS, ...NON_METALS].map((m) => [m.key, m.name])),
    default: 'gold',
    label: 'Selected',
  },
  recomputed: { type: 'bool', default: true, label: 'Show recomputed sRGB' },
};

const ABOUT =
  'Metals reflect a lot and in colour: their specular colour is all the colour they have. Non-metals reflect ' +
  'little and without colour (their colour comes from the diffuse term). The recomputed column applies the ' +
  'sRGB curve to the linear values. It agrees with the printed sRGB to within one unit of the last digit except ' +
  'for Plastic / Glass (Low), whose printed pair is inconsistent (marked): 0.03 linear is 0.19 in sRGB, while the ' +
  'printed 0.21 would be 0.036 linear. ' +
  'Use the links to load a material into the curves or onto the 3-D shape.';

const fmt = (xs) => xs.map((x) => x.toFixed(2)).join(', ');

function swatch(rgb, title) {
  const s = document.createElement('span');
  s.className = 'swatch big';
  s.style.background = rgbToHex(rgb);
  s.title = title;
  return s;
}

function buildTable(caption, rows, state, { metal, onPick, onSelect }) {
  const table = document.createElement('table');
  table.className = 'data-table f0-table';
  const cols = [
    'Material',
    'F(0°) linear',
    'F(0°) sRGB (talk)',
    ...(state.recomputed ? ['sRGB from linear'] : []),
    metal ? 'Measured n, k from' : 'IOR implied',
    'Colour',
    'Load into',
  ];
  table.innerHTML = `<caption>${caption}</caption><thead><tr>${cols.map((c) => `<th scope="col">${c}</th>`).join('')}</tr></thead>`;
  const body = table.createTBody();
  for (const m of rows) {
    const tr = body.insertRow();
    tr.dataset.material = m.key;
    if (m.key === state.selected) tr.classList.add('selected');
    const th = document.createElement('th');
    th.scope = 'row';
    th.textContent = m.name;
    tr.append(th);
    tr.insertCell().textContent = fmt(m.linear);
    tr.insertCell().textContent = fmt(m.srgb);
    const recomputed = m.linear.map(linearToSrgb);
    if (state.recomputed) {
      const cell = tr.insertCell();
      cell.textContent = fmt(recomputed);
      if (m.note) {
        cell.classList.add('mismatch');
        cell.textContent += ' ≠ printed';
        cell.title = m.note;
        th.title = m.note;
      }
    }
    tr.insertCell().textContent = metal ? measuredSource(m.key) : `n ≈ ${iorFromF0(m.linear[0]).toFixed(3)}`;
    const sw = tr.insertCell();
    sw.append(swatch(m.srgb, `${m.name}: sRGB ${fmt(m.srgb)}`));
    const links = tr.insertCell();
    links.className = 'links';
    for (const [target, text, params] of [
      ['fresnel-curves', 'curves', `materials=${m.key}`],
      ['fresnel-zones', '3-D', `material=${m.key}&mode=fresnel-nv`],
    ]) {
      const a = document.createElement('a');
      a.href = `embed.html?w=${target}&${params}`;
      a.textContent = text;
      a.setAttribute('aria-label', `Load ${m.name} into ${target}`);
      a.addEventListener('click', (e) => {
        if (onPick?.(m.key, target)) e.preventDefault();
      });
      links.append(a);
    }
    tr.addEventListener('click', (e) => {
      if (e.target.closest('a')) return;
      onSelect(m.key);
    });
    tr.tabIndex = 0; // a row is selected by Enter or Space as by a click
    tr.title = `Select ${m.name}`;
    tr.addEventListener('keydown', (e) => {
      if ((e.key !== 'Enter' && e.key !== ' ') || e.target !== tr) return;
      e.preventDefault();
      onSelect(m.key);
    });
  }
  return table;
}

/** options.onPick(materialKey, targetWidget) -> true when the page handled it (no navigation). */
const TERMS_USED = ['linearToSrgb', 'srgbToLinear'];

export function createF0Tables(container, initialState = {}, { onStateChange, onPick, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'f0-tables',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const holder = document.createElement('div');
  holder.className = 'f0-tables';
  shell.view.append(holder);
  const source = document.createElement('p');
  source.className = 'source';
  const notes = [...METALS, ...NON_METALS]
    .filter((m) => m.note)
    .map((m) => ` ${m.name}: ${m.note}`)
    .join('');
  source.textContent = `Tables: ${TABLE_SOURCE}. Swatches show the printed sRGB value.${notes}`;

  const render = () => {
    const onSelect = (key) => update({ selected: key });
    const focused = holder.contains(document.activeElement)
      ? document.activeElement.closest('tr')?.dataset.material
      : null;
    holder.replaceChildren(
      buildTable('Normal-incidence Fresnel for metals', METALS, shell.state, { metal: true, onPick, onSelect }),
      buildTable('Normal-incidence Fresnel for non-metals', NON_METALS, shell.state, {
        metal: false,
        onPick,
        onSelect,
      }),
      source,
    );
    if (focused) holder.querySelector(`tr[data-material="${focused}"]`)?.focus(); // keep the keyboard's place
    const m = [...METALS, ...NON_METALS].find((x) => x.key === shell.state.selected);
    const metal = METALS.includes(m);
    shell.describe(
      `Selected: ${m.name}, a ${metal ? 'metal' : 'non-metal'}; F(0°) linear ${fmt(m.linear)}, sRGB ${fmt(m.srgb)}` +
        `${metal ? '' : `, so an index of refraction near ${iorFromF0(m.linear[0]).toFixed(3)}`}.`,
    );
  };

  const update = shell.connect({ title: 'F0 tables', onChanged: render, onStateChange });
  render();

  return {
    update,
    getState: () => shell.state,
    dispose: shell.dispose,
  };
}

export const widget = { name: 'f0-tables', schema, create: createF0Tables, terms: TERMS_USED };
