// anisotropic-microsurface, the plot: G1 against the light's azimuth, Smith's curve and the ray-traced points.
import { AZIMUTHS_CURVE, smithCurve } from './model.js';

/** The plot spec (core/ui/plot.js) for the state, the surface and the sweep's data so far (sweep.js). */
export function azimuthPlotSpec(state, surface, data) {
  // plain arrays: a typed array would turn the azimuths not yet measured (null) into 0
  const at = (values) => Array.from(AZIMUTHS_CURVE, (p) => (p % 15 === 0 ? values[p / 15] : null));
  const smith = smithCurve(surface, state.theta);
  // G1 up to 1, from a tenth below the lowest value: near n (θ = 30°) every value is within 1e-6 of 1, and an
  // automatic range that narrow left the plot's library no room for its ticks (it threw)
  const lowest = Math.min(...smith, ...[...data.measured, ...data.away].filter((x) => x !== null));
  return {
    title: `Share of facets a light ${state.theta}° from n reaches, G1, against its azimuth: ray-traced vs Smith`,
    xLabel: 'Light azimuth from t, φ (degrees)',
    yLabel: 'G1 (share of lit facets)',
    x: { min: 0, max: 180 },
    y: { min: Math.max(0, Math.min(0.9, Math.floor(10 * lowest) / 10)), max: 1 },
    legend: true,
    xValues: (u, t) => t.map((v) => `${v}°`),
    series: [
      { label: 'Smith G1, anisotropic Beckmann', stroke: '#0072b2' },
      { label: 'ray-traced, all facets', stroke: '#d55e00', width: 0, points: true },
      { label: 'ray-traced, facets tilted away', stroke: '#009e73', width: 0, points: true },
    ],
    data: [AZIMUTHS_CURVE, smith, at(data.measured), at(data.away)],
    filename: 'anisotropic-microsurface-g1',
    height: 260,
  };
}
