// The BRDF lobe's readout: F, D, G and f of each BRDF at the chosen l and v, and, with multiple scattering, the
// Kulla–Conty lobe there beside single scattering; for OpenPBR, each layer's part there, which is also the key to
// the polar plot's lines.
import { factorsAt, factorsOf, kullaContyAt } from './model.js';
import { LAYER_KEYS, OPENPBR_LAYERS, layersAt } from './openpbr-lobe.js';
import { luminanceRec709 } from '../../math/color.js';
import { viewAzimuth } from './azimuths.js';

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

/** OpenPBR's parts at (l, v): each layer's RGB and luminance, its share of the whole, and the sum. */
function layersTable({ l, v, A }) {
  const parts = layersAt(l, v, A);
  const whole = [0, 1, 2].map((c) => LAYER_KEYS.reduce((s, k) => s + parts[k][c], 0));
  const Y = luminanceRec709(whole);
  const rgb = (x) => x.map((c) => `<td>${c.toPrecision(3)}</td>`).join('');
  const rows = LAYER_KEYS.map((k) => {
    const y = luminanceRec709(parts[k]);
    const key = OPENPBR_LAYERS[k];
    const swatch = `<span class="layer-key" data-color="${key.color}" aria-hidden="true"></span>`;
    const share = Y > 0 ? `${((100 * y) / Y).toFixed(1)}%` : '—';
    return (
      `<tr data-layer="${k}"><td>${swatch}${key.short}</td>${rgb(parts[k])}<td>${y.toPrecision(4)}</td>` +
      `<td>${share}</td></tr>`
    );
  });
  const sum = `<td>sum (A)</td>${rgb(whole)}<td>${Y.toPrecision(4)}</td><td></td>`;
  const total = `<tr data-layer="all">${sum}</tr>`;
  return (
    '<div class="table-scroll layers-scroll" tabindex="0" role="region" aria-label="OpenPBR’s layers at l and v">' +
    '<table class="data-table compact openpbr-layers"><caption>OpenPBR’s layers at (l, v) (1/sr; Y: luminance, ' +
    'the lobe’s radius)</caption><thead><tr><th>layer</th><th>R</th><th>G</th><th>B</th><th>Y</th>' +
    `<th>share of Y</th></tr></thead><tbody>${rows.join('')}${total}</tbody></table></div>`
  );
}

/** The azimuths in the caption when they matter: an anisotropic A, or a view off the plane of incidence. */
const azimuths = (state) =>
  state.anisotropy > 0 || state.viewPhi
    ? ` (azimuths from t: l ${state.lightPhi}°, v ${viewAzimuth(state)}°, Δφ ${state.viewPhi}° off the plane)`
    : '';

export function createReadout(container) {
  const readout = document.createElement('div');
  container.append(readout);
  return {
    draw(state, scene) {
      const { a } = scene;
      const caption =
        `At l = ${state.lightTheta}°, v = ${state.viewTheta}°${azimuths(state)}: n·l ${a.nl.toFixed(3)}, ` +
        `n·v ${a.nv.toFixed(3)}, ` +
        `n·h ${a.nh.toFixed(3)}, l·h ${a.lh.toFixed(3)}`;
      const rows = [scene.A, scene.B].filter(Boolean).map((p) => row(scene, p));
      readout.innerHTML =
        `<table class="data-table compact"><caption>${caption}</caption><thead><tr>${tableHead(state)}</tr></thead>` +
        `<tbody>${rows.join('')}</tbody></table>` +
        (scene.ms.lobe ? multipleLine(state, scene) : '') +
        (scene.A.openpbr && state.openpbrParts ? layersTable(scene) : '');
      // the key's colours through the CSSOM: the page's CSP allows no style attribute in markup
      for (const key of readout.querySelectorAll('.layer-key')) key.style.borderTopColor = key.dataset.color;
    },
  };
}
