// microfacets, the table under the cut: at the light's angle, the shadowed share ray-traced and by Smith.
import { shadowedShare } from './words.js';

/**
 * The table at the light's angle: shadowed share ray-traced (`measured` G1) and by Smith (`smith`), and the
 * rays drawn that bounce twice.
 */
export function statsHtml(state, { measured, smith, twice }) {
  const row = (label, value) => `<tr><td>${label}</td><td>${value}</td></tr>`;
  return (
    `<table class="data-table compact"><caption>At the light angle ${Math.abs(state.lightTheta)}°</caption><tbody>` +
    row('shadowed share of facets facing the light, ray-traced', shadowedShare(measured, 2)) +
    row('the same, predicted by Smith (1 − G1)', shadowedShare(smith, 2)) +
    row('rays drawn that bounce twice', `${twice} of ${state.rays}`) +
    '</tbody></table>'
  );
}
