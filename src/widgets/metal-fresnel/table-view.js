// metal-fresnel, the table: every channel of the talk's five metals with each model's parameters and worst error,
// the chosen metal's rows marked.
import { METAL_MODELS } from './models.js';
import { CHANNELS } from './model.js';
import { TABLE_CAPTION, TABLE_HEADS, errorWords, tableSummary } from './words.js';

/** [summary, table] of errorTable's rows, in a scroll box (it is wider than a phone), under a line naming the worst. */
export function buildErrorTable(rows, selected) {
  const summary = document.createElement('p');
  summary.className = 'metal-summary';
  summary.textContent = tableSummary(rows);
  const table = document.createElement('table');
  table.className = 'data-table compact metal-errors';
  const caption = table.createCaption();
  caption.textContent = TABLE_CAPTION;
  const head = table.createTHead().insertRow();
  for (const text of TABLE_HEADS) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = text;
    head.append(th);
  }
  const body = table.createTBody();
  for (const r of rows) {
    const tr = body.insertRow();
    if (r.key === selected) tr.className = 'selected';
    const th = document.createElement('th');
    th.scope = 'row';
    th.textContent = r.name;
    tr.append(th);
    for (const text of [
      CHANNELS[r.channel],
      r.fit.f0.toFixed(3),
      r.fit.tint.toFixed(3),
      r.fit.edgeTint.toFixed(3),
      ...Object.keys(METAL_MODELS).map((m) => errorWords(r.worst[m].value)),
    ])
      tr.insertCell().textContent = text;
  }
  const scroll = document.createElement('div');
  scroll.className = 'table-scroll';
  scroll.tabIndex = 0; // a scrolling region is reachable by keyboard
  scroll.setAttribute('role', 'region');
  scroll.setAttribute('aria-label', 'Worst errors of the three approximations, every metal and channel');
  scroll.append(table);
  return [summary, scroll];
}
