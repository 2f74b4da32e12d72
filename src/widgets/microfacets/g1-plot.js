// microfacets, the plot: the share of microfacets the light reaches, ray-traced at every 5° against Smith's G1.
import { smithCurve } from './model.js';

/** The plot spec (core/ui/plot.js) for the state and the G1 measured so far (g1-sweep.js). */
export function g1PlotSpec(state, g1) {
  const curve = smithCurve(state);
  // a plain array: a typed array would turn the angles not yet measured (null) into 0
  const measured = Array.from(curve.xs, (d) => (d % 5 === 0 ? g1.measured[d / 5] : null));
  return {
    title: 'Share of microfacets the light reaches, G1: ray-traced vs Smith',
    xLabel: 'Light angle from the mean normal (degrees)',
    yLabel: 'G1',
    x: { min: 0, max: 90 },
    y: { min: 0, max: 1.02 },
    xValues: (u, t) => t.map((v) => `${v}°`),
    series: [
      { label: 'Smith G1', stroke: '#0072b2' },
      { label: 'ray-traced profile', stroke: '#d55e00', width: 0, points: true },
    ],
    data: [curve.xs, curve.ys, measured],
    filename: 'microsurface-g1',
    height: 240,
  };
}
