// The white furnace's table: per roughness, E head-on, E's cosine-weighted average and the energy lost.

/** The table's head: E_avg = 2∫E(μ) μ dμ weights each direction by its cosine (Kulla & Conty 2017). */
export const HEAD =
  '<th>α</th><th>E at normal incidence</th><th>E<sub>avg</sub> = 2∫E(μ) μ dμ (cosine-weighted average)</th>' +
  '<th>energy lost on average</th>';

const row = (d) =>
  `<tr><td><span class="swatch" style="background:${d.stroke}"></span> ${d.alpha}</td>` +
  `<td>${d.atNormal.toFixed(4)}</td><td>${d.avg.toFixed(4)}</td><td>${((1 - d.avg) * 100).toFixed(1)}%</td></tr>`;

export function createAlbedoTable(container) {
  const table = document.createElement('div');
  container.append(table);
  return {
    draw(sweep) {
      table.innerHTML =
        '<table class="data-table compact"><caption>Albedo with F = 1 (GGX, height-correlated Smith)</caption>' +
        `<thead><tr>${HEAD}</tr></thead><tbody>${sweep.map(row).join('')}</tbody></table>`;
    },
  };
}
