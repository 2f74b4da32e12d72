// subsurface-scale's plot: how far from the entry point the light comes back out, with the shading sample marked.
import { createPlot } from '../../core/ui/plot.js';
import { withAlpha } from '../../core/ui/palettes.js';
import { histogram, histogramRange } from './model.js';

function plotSpec(state, stats) {
  const maxDist = histogramRange(state, stats);
  const { xs, ys } = histogram(stats, maxDist);
  return {
    title: 'Where the light comes back out: distance from the entry point',
    xLabel: 'Entry-to-exit distance (mm)',
    yLabel: 'light per mm',
    x: { min: 0, max: maxDist },
    y: null,
    legend: false,
    series: [{ label: 'exiting light', stroke: '#d55e00' }],
    data: [xs, ys],
    bands: [{ from: 0, to: state.pixel, color: withAlpha('#009e73', 0.15), label: 'inside the shading sample' }],
    filename: 'subsurface-exit-distance',
    height: 220,
  };
}

/** `show(state, stats)` redraws; `dispose()`. */
export function createExitPlot(container, state, stats) {
  const plot = createPlot(container, plotSpec(state, stats));
  return { show: (s, st) => plot.setData(plotSpec(s, st)), dispose: () => plot.dispose() };
}
