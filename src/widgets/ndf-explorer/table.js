// The NDF explorer's table: each NDF's parameters at the matched width and its normalisation, measured.
import { describeParams } from './words.js';

const CAPTION = 'Normalisation, measured: ∫ D(m)(n·m) dω over the hemisphere (Simpson, 4000 intervals)';
const HEAD = '<th>NDF</th><th>parameters at this width</th><th>∫ D (n·m) dω</th><th>|error|</th><th>D(0°)</th>';

const row = (c) =>
  `<tr><td><span class="swatch" style="background:${c.stroke}"></span> ${c.label}</td>` +
  `<td>${describeParams(c.key, c.p)}</td><td>${c.integral.toFixed(7)}</td>` +
  `<td>${Math.abs(c.integral - 1).toExponential(1)}</td><td>${c.values[0].toPrecision(4)}</td></tr>`;

export function createNdfTable(container) {
  // a box of its own that scrolls: the table is wider than a phone (its five columns) and must not widen the page
  const table = Object.assign(document.createElement('div'), { className: 'table-scroll', tabIndex: 0 });
  table.setAttribute('role', 'region');
  table.setAttribute('aria-label', 'Normalisation of each NDF, measured');
  container.append(table);
  return {
    draw(curves) {
      table.innerHTML =
        `<table class="data-table compact"><caption>${CAPTION}</caption><thead><tr>${HEAD}</tr></thead>` +
        `<tbody>${curves.map(row).join('')}</tbody></table>`;
    },
  };
}
