// fresnel-curves, the two plots: reflectance against angle (exact solid, Schlick dashed, metals labelled by
// channel) and Schlick's error, both over the zone bands.
import { CHANNELS } from './model.js';

const xAxis = {
  xLabel: 'Angle of incidence θ (degrees)',
  x: { min: 0, max: 90 },
  xValues: (u, ticks) => ticks.map((t) => `${t}°`),
};

/** The reflectance plot's spec (core/ui/plot.js) for the series of model.js's buildSeries. */
export function reflectanceSpec({ angles, curves, bands }, state) {
  const series = [];
  const data = [angles];
  for (const c of curves) {
    series.push({ label: `${c.label} exact`, stroke: c.stroke, width: 2 });
    data.push(c.exact);
    if (state.schlick) {
      series.push({ label: `${c.label} Schlick`, stroke: c.stroke, width: 1.5, dash: [6, 4] });
      data.push(c.schlick);
    }
  }
  const at = Math.round(4 / (angles[1] - angles[0])); // channel labels at 4°, staggered
  const annotations = curves
    .filter((c) => c.spec.metal)
    .map((c, i) => ({ x: 2 + 5 * (i % 3), y: c.exact[at], text: CHANNELS[c.spec.channel], color: c.stroke }));
  return {
    title: 'Fresnel reflectance F(θ) — solid: exact, dashed: Schlick',
    ...xAxis,
    yLabel: 'Reflectance (linear)',
    y: { min: 0, max: 1 },
    series,
    data,
    bands,
    annotations,
    legend: false,
    filename: 'fresnel-reflectance',
    height: 320,
  };
}

/** The error plot's spec: Schlick − exact for each curve. */
export function errorSpec({ angles, curves, bands }) {
  return {
    title: 'Schlick − exact',
    ...xAxis,
    yLabel: 'Error (reflectance)',
    y: null,
    series: curves.map((c) => ({ label: c.label, stroke: c.stroke, width: 1.5 })),
    data: [angles, ...curves.map((c) => c.error)],
    bands,
    legend: false,
    filename: 'fresnel-schlick-error',
    height: 220,
  };
}
