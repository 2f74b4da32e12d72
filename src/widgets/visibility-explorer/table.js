// The visibility explorer's table: each term's largest difference from height-correlated Smith up to 80°.

const CAPTION = 'Largest difference from height-correlated Smith up to 80°, in these directions';

const row = (c) =>
  `<tr><td><span class="swatch" style="background:${c.stroke}"></span> ${c.label}</td>` +
  `<td>${c.worst.toFixed(1)}%</td></tr>`;

export function createVisibilityTable(container) {
  const table = document.createElement('div');
  container.append(table);
  return {
    draw(curves) {
      table.innerHTML =
        `<table class="data-table compact"><caption>${CAPTION}</caption>` +
        '<thead><tr><th>Term</th><th>max |error|</th></tr></thead>' +
        `<tbody>${curves.map(row).join('')}</tbody></table>`;
    },
  };
}
