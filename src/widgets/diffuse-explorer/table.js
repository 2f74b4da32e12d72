// The diffuse explorer's table: how flat the disc looks, from the profile at the centre and near the rim.
import { termLabel } from '../../math/catalogue/index.js';
import { PROFILE_XS, modelColor } from './model.js';

/** Where the flatness table reads the profile: 90% of the way to the rim, on the light's side. */
const RIM = 0.9;
const CENTRE_AT = PROFILE_XS.indexOf(0);
const RIM_AT = PROFILE_XS.findIndex((x) => Math.abs(x - RIM) < 1e-9);
const CAPTION =
  'How flat the disc looks: Lo / c_light at the centre and ' + `${RIM * 100}% of the way to the rim (light’s side)`;

function row(key, values) {
  const [c, r] = [values[CENTRE_AT], values[RIM_AT]];
  return (
    `<tr><td><span class="swatch" style="background:${modelColor(key)}"></span> ${termLabel('diffuse', key)}</td>` +
    `<td>${c.toFixed(4)}</td><td>${r.toFixed(4)}</td><td>${c > 1e-9 ? (r / c).toFixed(3) : '—'}</td></tr>`
  );
}

export function createFlatnessTable(container) {
  const table = document.createElement('div');
  container.append(table);
  return {
    /** profile: one array over PROFILE_XS per chosen model. */
    draw(state, profile) {
      table.innerHTML =
        `<table class="data-table compact"><caption>${CAPTION}</caption>` +
        '<thead><tr><th>Model</th><th>centre</th><th>at 0.9 R</th><th>rim / centre</th></tr></thead>' +
        `<tbody>${state.diffuse.map((k, i) => row(k, profile[i])).join('')}</tbody></table>`;
    },
  };
}
