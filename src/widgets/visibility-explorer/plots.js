// The visibility explorer's two plots: G against angle, and each term's difference from height-correlated Smith.
import { createPlot } from '../../core/ui/plot.js';
import { ANGLES } from './model.js';
import { angleAxisLabel } from './words.js';
import { createAzimuthPlot } from './azimuth.js';

const axis = (state) => ({
  xLabel: angleAxisLabel(state),
  x: { min: 0, max: 90 },
  xValues: (u, t) => t.map((v) => `${v}°`),
});
const seriesOf = (curves) => curves.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash }));

const gSpec = (curves, state) => ({
  title: `G = V·(n·l)(n·v), the visibility term V times the foreshortening, at α = ${state.alpha}`,
  ...axis(state),
  yLabel: 'G = V (n·l)(n·v)',
  y: { min: 0, max: 1.05 },
  series: seriesOf(curves),
  data: [ANGLES, ...curves.map((c) => c.G)],
  filename: 'visibility-G',
  height: 280,
});

const errorSpec = (curves, state) => ({
  title: 'Difference from height-correlated Smith (%)',
  ...axis(state),
  yLabel: 'error (%)',
  y: { min: -100, max: 100 },
  legend: false,
  series: seriesOf(curves),
  data: [ANGLES, ...curves.map((c) => c.error)],
  filename: 'visibility-error',
  height: 220,
});

export function createVisibilityPlots(container, curves, state) {
  const gPlot = createPlot(container, gSpec(curves, state));
  const errorPlot = createPlot(container, errorSpec(curves, state));
  const azimuth = createAzimuthPlot(container, state);
  return {
    draw(next, nextState) {
      gPlot.setData(gSpec(next, nextState));
      errorPlot.setData(errorSpec(next, nextState));
      azimuth.draw(nextState);
    },
    azimuthCurves: () => azimuth.curves(),
    dispose() {
      gPlot.dispose();
      errorPlot.dispose();
      azimuth.dispose();
    },
  };
}
