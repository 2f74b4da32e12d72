// surfaces' plot: where light goes after one reflection off a rough surface, ray traced against the microfacet
// prediction.
import { createPlot } from '../../core/ui/plot.js';
import { reflectionCone } from './model.js';

function plotSpec(s, profile) {
  const { xs, counts, predicted } = reflectionCone(s, profile);
  return {
    title: `Where light from ${s.theta}° goes after one reflection off a microsurface of roughness α = ${s.alpha}`,
    xLabel: 'Outgoing angle (°), mirror at −θ',
    yLabel: 'share per degree',
    x: { min: -90, max: 90 },
    y: null,
    series: [
      { label: 'ray-traced microsurface', stroke: '#d55e00' },
      { label: 'microfacet prediction', stroke: '#0072b2', dash: [6, 4] },
    ],
    data: [xs, counts, predicted],
    bands: [],
    xValues: (u, t) => t.map((v) => `${v}°`),
    filename: 'reflection-cone',
    height: 230,
  };
}

/** `show(state, profile)` redraws; `dispose()`. */
export function createConePlot(container, state, profile) {
  const plot = createPlot(container, plotSpec(state, profile));
  return { show: (s, p) => plot.setData(plotSpec(s, p)), dispose: () => plot.dispose() };
}
