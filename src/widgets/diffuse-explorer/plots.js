// The diffuse explorer's plots: the brightness across a sphere (the rough "full moon" flattening), the radiance
// as the light sweeps past a fixed view, and the light sent back by specular plus diffuse against the view angle.
import { sigmaText } from '../../core/ui/sigma-range.js';
import { createPlot } from '../../core/ui/plot.js';
import { termLabel } from '../../math/catalogue/index.js';
import { PROFILE_XS, SWEEP_XS, TRADE_XS, modelColor } from './model.js';

const degValues = (u, ticks) => ticks.map((t) => `${t}°`);
const seriesOf = (state) => state.diffuse.map((k) => ({ label: termLabel('diffuse', k), stroke: modelColor(k) }));

const profileSpec = (state, profile) => ({
  title: `Brightness across the sphere, through the side the light is on (${sigmaText(state.sigma)})`,
  xLabel: 'Diameter position (radii, + = light side)',
  yLabel: 'Lo / c_light',
  x: { min: -1, max: 1 },
  y: null,
  series: seriesOf(state),
  data: [PROFILE_XS, ...profile],
  filename: 'diffuse-profile',
  height: 260,
});

function sweepSpec(state, sweep) {
  const tv = state.viewTheta;
  return {
    title:
      `Radiance of a flat patch seen from θv = ${tv}°, the light sweeping through the plane of n and v ` +
      `(${sigmaText(state.sigma)})`,
    xLabel: 'Light angle θl (degrees, + = viewer’s side)',
    yLabel: 'Lo / c_light',
    x: { min: -90, max: 90 },
    y: null,
    xValues: degValues,
    series: seriesOf(state),
    data: [SWEEP_XS, ...sweep],
    bands: [
      { from: tv - 0.6, to: tv + 0.6, color: '#e69f0055', label: 'l = v' },
      { from: -tv - 0.6, to: -tv + 0.6, color: '#56b4e955', label: 'mirror' },
    ],
    filename: 'diffuse-light-sweep',
    height: 260,
  };
}

const tradeOffSpec = (state, { totals, specular }) => ({
  title:
    `Light sent back: smooth specular F(θv) (F0 = ${state.f0}) plus each diffuse albedo ` + `(c_diff = ${state.cdiff})`,
  xLabel: 'View angle θv (degrees)',
  yLabel: 'returned / incident',
  x: { min: 0, max: 90 },
  y: { min: 0, max: 2 },
  xValues: degValues,
  series: [
    ...seriesOf(state).map((s) => ({ ...s, label: `F + ${s.label}` })),
    { label: 'F alone (specular)', stroke: '#777777', dash: [6, 4] },
    { label: 'all the incident light', stroke: '#000000', dash: [2, 3], width: 1 },
  ],
  data: [TRADE_XS, ...totals, specular, TRADE_XS.map(() => 1)],
  filename: 'diffuse-specular-tradeoff',
  height: 260,
});

/** A plot drawn by spec(state, data): draw(state, data), plotted() (its [xs, ...series] as uPlot holds them). */
function specPlot(container, spec, state, data) {
  const plot = createPlot(container, spec(state, data));
  return {
    draw: (nextState, nextData) => plot.setData(spec(nextState, nextData)),
    plotted: () => plot.uplot.data.map((col) => Array.from(col)),
    dispose: () => plot.dispose(),
  };
}

/** profile: one array over PROFILE_XS per model, as model.js's profile() returns them. */
export const createProfilePlot = (container, state, profile) => specPlot(container, profileSpec, state, profile);
/** sweep: one array over SWEEP_XS per model, as lightSweep() returns them. */
export const createSweepPlot = (container, state, sweep) => specPlot(container, sweepSpec, state, sweep);
/** tradeOff: { totals, specular } as tradeOff() returns it. */
export const createTradeOffPlot = (container, state, tradeOff) => specPlot(container, tradeOffSpec, state, tradeOff);
