// f0-tables, one table: a row per material with its printed and recomputed values, a swatch, and links that
// load it into the other Fresnel widgets. A row is selected by a click, or by Enter or Space.
import { rgbToHex } from '../../core/ui/palettes.js';
import { measuredSource } from '../../math/index.js';
import { impliedIor, loadTargets, recomputedSrgb } from './model.js';
import { channels, columns } from './words.js';

function swatch(rgb, title) {
  const s = document.createElement('span');
  s.className = 'swatch big';
  s.style.background = rgbToHex(rgb);
  s.title = title;
  return s;
}

/** The links of a row; `onPick(key, widget)` returns true when the page loaded it in place (no navigation). */
function loadLinks(m, onPick) {
  return loadTargets(m.key).map(([target, text, params, where]) => {
    const a = document.createElement('a');
    a.href = `embed.html?w=${target}&${params}`;
    a.textContent = text;
    // the name starts with the words shown, so a voice-control user can say them (WCAG 2.5.3, label in name)
    a.setAttribute('aria-label', `${text}: load ${m.name} ${where}`);
    a.addEventListener('click', (e) => {
      if (onPick?.(m.key, target)) e.preventDefault();
    });
    return a;
  });
}

function selectable(tr, m, onSelect) {
  tr.addEventListener('click', (e) => {
    if (e.target.closest('a')) return;
    onSelect(m.key);
  });
  tr.tabIndex = 0;
  tr.title = `Select ${m.name}`;
  tr.addEventListener('keydown', (e) => {
    if ((e.key !== 'Enter' && e.key !== ' ') || e.target !== tr) return;
    e.preventDefault();
    onSelect(m.key);
  });
}

function materialRow(body, m, state, { metal, onPick, onSelect }) {
  const tr = body.insertRow();
  tr.dataset.material = m.key;
  if (m.key === state.selected) tr.classList.add('selected');
  const th = document.createElement('th');
  th.scope = 'row';
  th.textContent = m.name;
  tr.append(th);
  tr.insertCell().textContent = channels(m.linear);
  tr.insertCell().textContent = channels(m.srgb);
  if (state.recomputed) {
    const cell = tr.insertCell();
    cell.textContent = channels(recomputedSrgb(m));
    if (m.note) {
      cell.classList.add('mismatch');
      cell.textContent += ' ≠ printed';
      cell.title = m.note;
      th.title = m.note;
    }
  }
  tr.insertCell().textContent = metal ? measuredSource(m.key) : `n ≈ ${impliedIor(m).toFixed(3)}`;
  tr.insertCell().append(swatch(m.srgb, `${m.name}: sRGB ${channels(m.srgb)}`));
  const links = tr.insertCell();
  links.className = 'links';
  links.append(...loadLinks(m, onPick));
  selectable(tr, m, onSelect);
}

/** One of model.js's TABLES as a table for the state; `onSelect(key)` selects a row, `onPick` see loadLinks. */
export function buildTable({ caption, rows, metal }, state, { onPick, onSelect }) {
  const table = document.createElement('table');
  table.className = 'data-table f0-table';
  const heads = columns(state, metal).map((c) => `<th scope="col">${c}</th>`);
  table.innerHTML = `<caption>${caption}</caption><thead><tr>${heads.join('')}</tr></thead>`;
  const body = table.createTBody();
  for (const m of rows) materialRow(body, m, state, { metal, onPick, onSelect });
  return table;
}
