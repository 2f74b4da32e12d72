// The measured-BRDF widget's NDF plot: the NDF slice the measurement implies against each fit's D / D(0), on a
// log scale, where the tails part.
import { createPlot } from '../../core/ui/plot.js';
import { seriesStyle } from '../../core/ui/palettes.js';
import { FIT_MODELS } from '../../measured/fit.js';
import { THETA_H_DEG, bestFit, fittedNdfSlice, measuredNdfSlice } from './model.js';

const MODELS = Object.keys(FIT_MODELS);

function ndfSpec(measured, fits, overlay) {
  const keys = MODELS.filter((k) => fits[k]);
  const best = bestFit(fits);
  const label = best
    ? `measured θd = 0 slice, less the ${FIT_MODELS[best.model].label} fit’s diffuse, ÷ its V`
    : 'measured θd = 0 slice';
  const fitSeries = (k) => ({
    label: `${FIT_MODELS[k].label} fit`,
    ...seriesStyle(MODELS.indexOf(k)),
    width: k === overlay ? 3 : 1.5,
  });
  const series = [{ label, stroke: '#000000', width: 2.5 }, ...keys.map(fitSeries)];
  const data = [
    measured ? measuredNdfSlice(measured.table, best) : THETA_H_DEG.map(() => null),
    ...keys.map((k) => fittedNdfSlice(fits[k])),
  ];
  return {
    title:
      'The NDF the measurement implies, and the fits’ D / D(0) ' +
      `(log scale; thick: ${FIT_MODELS[overlay].label}, overlaid): the tails`,
    xLabel: 'θh (degrees)',
    yLabel: 'relative to the peak',
    x: { min: 0, max: 90 },
    y: { min: 1e-5, max: 2, log: true },
    xValues: (u, t) => t.map((v) => `${v}°`),
    legend: true,
    series,
    data: [THETA_H_DEG, ...data.map((d) => d.map((x) => (x > 1e-5 ? x : null)))],
    filename: 'measured-ndf',
    height: 280,
  };
}

/** `show(measured, fits, overlay)`: the table (or null), the fits so far, the overlaid model; `dispose()`. */
export function createNdfPlot(container, overlay) {
  const plot = createPlot(container, ndfSpec(null, {}, overlay));
  return { show: (measured, fits, o) => plot.setData(ndfSpec(measured, fits, o)), dispose: () => plot.dispose() };
}
