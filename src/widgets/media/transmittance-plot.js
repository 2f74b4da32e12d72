// media's plot: the light a medium leaves unscattered and unabsorbed against depth, per RGB channel, with the
// depth chosen marked.
import { createPlot } from '../../core/ui/plot.js';
import { SERIES_DASHES } from '../../core/ui/palettes.js';
import { MEDIA } from './schema.js';
import { DISTANCES, transmittanceCurves } from './model.js';
import { depthTick, plotTitle } from './words.js';

const CHANNELS = [
  ['red (650 nm)', '#d55e00'],
  ['green (550 nm)', '#009e73'],
  ['blue (450 nm)', '#0072b2'],
];

function plotSpec(state) {
  const m = MEDIA[state.medium];
  const d = 10 ** state.distance;
  return {
    title: plotTitle(m),
    xLabel: 'Depth d (m, log scale)',
    yLabel: 'transmittance',
    x: { min: 1e-3, max: 100, log: true },
    y: { min: 0, max: 1.02 },
    xValues: (u, t) => t.map(depthTick),
    series: CHANNELS.map(([label, stroke], i) => ({ label, stroke, dash: SERIES_DASHES[i] })),
    data: [DISTANCES, ...transmittanceCurves(m)],
    bands: [{ from: d / 1.06, to: d * 1.06, color: '#0000002a', label: '' }],
    filename: `transmittance-${state.medium}`,
    height: 240,
  };
}

/** `show(state)` redraws for a medium and depth; `dispose()`. */
export function createTransmittancePlot(container, state) {
  const plot = createPlot(container, plotSpec(state));
  return { show: (next) => plot.setData(plotSpec(next)), dispose: () => plot.dispose() };
}
