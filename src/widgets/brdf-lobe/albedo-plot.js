// The BRDF lobe's albedo plot: the directional albedo E(θv) of A and, with the overlay, B (dashed, as on the
// polar plot), all factors on, the view at its azimuth.
import { createPlot } from '../../core/ui/plot.js';
import { ALBEDO_ANGLES, albedoCurve } from './model.js';

/** turn: the view's Δφ off the plane of incidence (radians). */
function albedoSpec(specs, turn) {
  const series = specs.map((p, i) => ({
    label: p.label,
    stroke: i ? '#009e73' : '#d55e00',
    dash: i ? [6, 4] : undefined,
    values: albedoCurve(p, turn),
  }));
  return {
    title: 'Directional albedo E(θv) = ∫ f (n·l) dω (all factors on)',
    xLabel: 'View angle θv (degrees)',
    yLabel: 'E',
    x: { min: 0, max: 90 },
    y: null,
    xValues: (u, t) => t.map((v) => `${v}°`),
    series,
    data: [ALBEDO_ANGLES, ...series.map((s) => s.values)],
    filename: 'brdf-albedo',
    height: 250,
  };
}

export function createAlbedoPlot(container, specs, turn = 0) {
  const holder = document.createElement('div');
  holder.className = 'albedo-plot';
  container.append(holder);
  const plot = createPlot(holder, albedoSpec(specs, turn));
  return {
    draw: (next, nextTurn = 0) => plot.setData(albedoSpec(next, nextTurn)),
    dispose: () => plot.dispose(),
  };
}
