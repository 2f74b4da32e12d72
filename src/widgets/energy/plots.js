// The white furnace's two plots: the directional albedo E(θv) per roughness, and the energy lost, 1 − E.
import { createPlot } from '../../core/ui/plot.js';
import { ANGLES } from './model.js';

const axis = { xLabel: 'View angle θv (degrees)', x: { min: 0, max: 90 }, xValues: (u, t) => t.map((v) => `${v}°`) };
const seriesOf = (sweep) => sweep.map((d) => ({ label: `α = ${d.alpha}`, stroke: d.stroke, dash: d.dash }));

const albedoSpec = (sweep) => ({
  ...axis,
  title: 'Directional albedo E(θv) of one bounce (no compensation), F = 1',
  yLabel: 'E',
  y: { min: 0, max: 1.02 },
  series: seriesOf(sweep),
  data: [ANGLES, ...sweep.map((d) => d.E)],
  filename: 'albedo',
  height: 260,
});

const lossSpec = (sweep) => ({
  ...axis,
  title: 'Energy lost to ignoring multiple bounces, 1 − E',
  yLabel: '1 − E',
  y: { min: 0, max: 0.8 },
  legend: false,
  series: seriesOf(sweep),
  data: [ANGLES, ...sweep.map((d) => d.loss)],
  filename: 'energy-loss',
  height: 220,
});

export function createAlbedoPlots(container, sweep) {
  const albedoPlot = createPlot(container, albedoSpec(sweep));
  const lossPlot = createPlot(container, lossSpec(sweep));
  return {
    draw(next) {
      albedoPlot.setData(albedoSpec(next));
      lossPlot.setData(lossSpec(next));
    },
    dispose() {
      albedoPlot.dispose();
      lossPlot.dispose();
    },
  };
}
