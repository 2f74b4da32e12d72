// fresnel-curves, the readout under the plots: per curve, the values at the angle under the pointer and
// Schlick's worst error.
import { readoutCaption, readoutColumns } from './words.js';

function curveRow(body, c, i) {
  const tr = body.insertRow();
  const name = tr.insertCell();
  const sw = document.createElement('span');
  sw.className = 'swatch';
  sw.style.background = c.stroke;
  name.append(sw, ` ${c.label}`);
  const mark = c.spec.fitted ? '†' : '';
  for (const text of [
    `${c.spec.eta.toFixed(3)}${mark}`,
    `${c.spec.k.toFixed(3)}${mark}`,
    c.f0.toFixed(3),
    c.exact[i].toFixed(4),
    c.schlick[i].toFixed(4),
    Math.abs(c.maxError).toFixed(4),
    `${c.maxErrorAt.toFixed(2)}°`,
  ]) {
    tr.insertCell().textContent = text;
  }
}

/** Fills `el` with the table at the data index `index` (60° when null: the pointer is off the plots). */
export function renderReadout(el, { angles, curves }, index) {
  const i = index ?? angles.findIndex((a) => a >= 60);
  const theta = angles[i];
  const table = document.createElement('table');
  table.className = 'data-table compact readout';
  const heads = readoutColumns(theta).map((c) => `<th scope="col">${c}</th>`);
  table.innerHTML =
    `<caption>${readoutCaption(
      theta,
      curves.some((c) => c.spec.fitted),
    )}</caption>` + `<thead><tr>${heads.join('')}</tr></thead>`;
  const body = table.createTBody();
  curves.forEach((c) => curveRow(body, c, i));
  el.replaceChildren(table);
}
