// The BRDF lobe's readout: F, D, G and f of each BRDF at the chosen l and v, and, with multiple scattering, the
// Kulla–Conty lobe there beside single scattering.
import { factorsAt, factorsOf, kullaContyAt } from './model.js';

/** The table's head: a whole custom BRDF is no F·D·G/(4 n·l n·v). */
export const tableHead = (state) =>
  '<th>BRDF</th><th>F</th><th>D (1/sr)</th><th>G</th>' +
  `<th>${state.brdf === 'custom' ? 'f' : 'f = FDG/(4 n·l n·v)'} (1/sr)</th>`;

/** A factor's cell: '—' for a whole custom BRDF, which has none. */
const cell = (x, format) => `<td>${x === null ? '—' : format(x)}</td>`;

function row({ l, v, a }, p) {
  const t = factorsAt(l, v, a, p);
  const [fixed, precision] = [(x) => x.toFixed(4), (x) => x.toPrecision(4)];
  return (
    `<tr><td>${p.label}</td>${cell(t.F, fixed)}${cell(t.D, precision)}${cell(t.G, fixed)}` +
    `<td>${t.f.toPrecision(4)}</td></tr>`
  );
}

function multipleLine(state, { l, v, A }) {
  const multiple = kullaContyAt(state, l, v).toPrecision(3);
  return (
    `<p class="multiple-readout">Multiple scattering at v (A): Kulla–Conty ${multiple} /sr beside single ` +
    `scattering ${factorsOf(l, v, A).toPrecision(3)} /sr (dotted lobe; dots: the random walk, bars ± 2 ` +
    'standard errors).</p>'
  );
}

export function createReadout(container) {
  const readout = document.createElement('div');
  container.append(readout);
  return {
    draw(state, scene) {
      const { a } = scene;
      const caption =
        `At l = ${state.lightTheta}°, v = ${state.viewTheta}°: n·l ${a.nl.toFixed(3)}, n·v ${a.nv.toFixed(3)}, ` +
        `n·h ${a.nh.toFixed(3)}, l·h ${a.lh.toFixed(3)}`;
      const rows = [scene.A, scene.B].filter(Boolean).map((p) => row(scene, p));
      readout.innerHTML =
        `<table class="data-table compact"><caption>${caption}</caption><thead><tr>${tableHead(state)}</tr></thead>` +
        `<tbody>${rows.join('')}</tbody></table>` +
        (scene.ms.lobe ? multipleLine(state, scene) : '');
    },
  };
}
