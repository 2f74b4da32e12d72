// The measured-BRDF widget's lobe plot: f in the plane of incidence per channel, measured and (dashed) the
// overlaid fit, on a log scale.
import { createPlot } from '../../core/ui/plot.js';
import { FIT_MODELS } from '../../measured/fit.js';
import { VIEW_ANGLES, fitBRDF, planeOfIncidence } from './model.js';

const CHANNELS = [
  ['R', '#c0392b'],
  ['G', '#1e8449'],
  ['B', '#2e5cb8'],
];

const logRange = (arrays) => {
  const all = arrays.flat().filter((x) => x > 0);
  const max = all.length ? Math.max(...all) : 1;
  return { min: max * 1e-4, max: max * 2, log: true };
};
const positive = (values) => values.map((x) => (x > 0 ? x : null));

function lobeSpec(measured, fit, lightDeg) {
  const m = measured ? planeOfIncidence(measured.lookup, lightDeg) : [[], [], []];
  const f = fit ? planeOfIncidence(fitBRDF(fit), lightDeg) : null;
  const series = [
    ...CHANNELS.map(([c, stroke]) => ({ label: `measured ${c}`, stroke })),
    ...(f
      ? CHANNELS.map(([c, stroke]) => ({ label: `${FIT_MODELS[fit.model].label} fit ${c}`, stroke, dash: [6, 4] }))
      : []),
  ];
  const data = [...m, ...(f ?? [])].map((s) => positive(Array.from(VIEW_ANGLES, (_, i) => s[i])));
  return {
    title: `f in the plane of incidence, light at ${lightDeg}° (log scale; dashed: fit)`,
    xLabel: 'View angle θv (degrees; + on the mirror side)',
    yLabel: 'f (1/sr)',
    x: { min: -90, max: 90 },
    y: logRange([...m, ...(f ?? [])]),
    xValues: (u, t) => t.map((v) => `${v}°`),
    legend: true,
    series,
    data: [VIEW_ANGLES, ...data],
    filename: 'measured-lobe',
    height: 280,
  };
}

/** `show(measured, fit, lightDeg)`: either may be null (not read, not fitted yet); `dispose()`. */
export function createLobePlot(container, lightDeg) {
  const plot = createPlot(container, lobeSpec(null, null, lightDeg));
  return { show: (measured, fit, deg) => plot.setData(lobeSpec(measured, fit, deg)), dispose: () => plot.dispose() };
}
