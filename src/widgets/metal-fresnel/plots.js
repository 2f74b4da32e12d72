// metal-fresnel, the two plots: a metal's reflectance against angle per channel (exact solid, each approximation
// in its own dash) and each approximation's error (model − exact).
import { METAL_MODELS } from './models.js';
import { CHANNELS } from './model.js';

/** R, G, B in colours dark enough for their labels on white (≥ 4.5:1). */
export const CHANNEL_COLORS = ['#b3261e', '#137333', '#1a56c4'];

const xAxis = {
  xLabel: 'Angle of incidence θ (degrees)',
  x: { min: 0, max: 90 },
  xValues: (u, ticks) => ticks.map((t) => `${t}°`),
};

const shown = (state) => Object.keys(METAL_MODELS).filter((m) => state.models.includes(m));
/** The smallest value of any series: the plot starts at the tenth below it, where the dips show. */
const lowest = (series) => Math.min(...series.map((ys) => Math.min(...ys)));
const DASH_NAMES = { schlick: 'dashed', gulbrandsen: 'dotted', f82Tint: 'dash-dot' };
/** What each line style is: 'solid: exact, dashed: Schlick, …' for the shown models. */
export const lineKey = (state) =>
  ['solid: exact', ...shown(state).map((m) => `${DASH_NAMES[m]}: ${METAL_MODELS[m].label}`)].join(', ');

/** The reflectance plot's spec (core/ui/plot.js) for compareMetal's channels. */
export function reflectanceSpec(angles, channels, state, metalName) {
  const series = [];
  const data = [angles];
  for (const c of channels) {
    const stroke = CHANNEL_COLORS[c.channel];
    series.push({ label: `${CHANNELS[c.channel]} exact`, stroke, width: 2 });
    data.push(c.exact);
    for (const model of shown(state)) {
      series.push({
        label: `${CHANNELS[c.channel]} ${METAL_MODELS[model].label}`,
        stroke,
        width: 1.5,
        dash: METAL_MODELS[model].dash,
      });
      data.push(c.models[model].values);
    }
  }
  const at = Math.round(30 / (angles[1] - angles[0]));
  const annotations = channels.map((c) => ({
    x: 22 + 6 * c.channel,
    y: c.exact[at],
    text: CHANNELS[c.channel],
    color: CHANNEL_COLORS[c.channel],
  }));
  return {
    title: `${metalName}: reflectance F(θ) per channel (R, G, B) — ${lineKey(state)}`,
    ...xAxis,
    yLabel: 'Reflectance (linear)',
    y: { min: Math.floor(10 * lowest(data.slice(1))) / 10, max: 1 },
    series,
    data,
    bands: [],
    annotations,
    legend: false,
    filename: 'metal-fresnel-reflectance',
    height: 300,
  };
}

/** The error plot's spec: each shown approximation − exact, per channel. */
export function errorSpec(angles, channels, state) {
  const series = [];
  const data = [angles];
  for (const c of channels)
    for (const model of shown(state)) {
      series.push({
        label: `${CHANNELS[c.channel]} ${METAL_MODELS[model].label}`,
        stroke: CHANNEL_COLORS[c.channel],
        width: 1.5,
        dash: METAL_MODELS[model].dash,
      });
      data.push(c.models[model].error);
    }
  return {
    title: `Approximation − exact (${lineKey(state).replace('solid: exact, ', '')})`,
    ...xAxis,
    yLabel: 'Error (reflectance)',
    y: null,
    series,
    data,
    bands: [],
    legend: false,
    filename: 'metal-fresnel-error',
    height: 220,
  };
}
