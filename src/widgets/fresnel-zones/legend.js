// fresnel-zones, the legend under the view: a swatch per zone with its measured share (and the exact one where
// it is known), and in the weighted mode the shares averaged over light directions.
import { ZONE_LABELS, ZONE_PALETTES } from '../../core/ui/palettes.js';
import { analyticShares, isWeighted } from './model.js';
import { averageText, legendHead, shareText } from './words.js';

function zoneRow(color, i, share, exact) {
  const row = document.createElement('div');
  row.className = 'zone-row';
  row.dataset.zone = i;
  const sw = document.createElement('span');
  sw.className = 'swatch';
  sw.style.background = color;
  const label = document.createElement('span');
  label.textContent = ZONE_LABELS[i];
  const pct = document.createElement('span');
  pct.className = 'pct';
  pct.textContent = shareText(share, exact);
  row.append(sw, label, pct);
  return row;
}

/** `element`, filled by `show(state, { zoneShares, averageShares })`. */
export function createZoneLegend() {
  const element = document.createElement('div');
  element.className = 'zone-legend';
  return {
    element,
    show(state, { zoneShares, averageShares }) {
      const analytic = analyticShares(state);
      const head = document.createElement('div');
      head.className = 'zone-legend-head';
      head.textContent = legendHead(state, analytic);
      const rows = ZONE_PALETTES[state.palette].colors.map((c, i) => zoneRow(c, i, zoneShares[i], analytic?.[i]));
      element.replaceChildren(head, ...rows);
      if (isWeighted(state) && averageShares) {
        const average = document.createElement('div');
        average.className = 'zone-average';
        average.textContent = averageText(state, averageShares);
        element.append(average);
      }
    },
  };
}
