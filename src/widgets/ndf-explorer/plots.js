// The NDF explorer's two plots: D(θh) on a linear axis, and on a log axis for the tails; with a measured slice
// the log plot puts every curve over its own peak and adds the measurement.
import { createPlot } from '../../core/ui/plot.js';
import { ANGLES, TAIL_DEG, THETA_AXIS as axis, logAxes, measuredOnAngles, tailsAt } from './model.js';
import { describeAnisotropy, describeTails } from './words.js';
import { createSlopeMaps } from './slope-map.js';
import { ANISOTROPY_CONVENTIONS, anisotropicAlphas } from '../../math/anisotropic.js';

const seriesOf = (curves) => curves.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash }));

const linearSpec = (curves) => ({
  ...axis,
  title: 'D(θh), linear',
  yLabel: 'D (1/sr)',
  y: null,
  legend: true,
  series: seriesOf(curves),
  data: [ANGLES, ...curves.map((c) => c.values)],
  filename: 'ndf-linear',
  height: 260,
});

function absoluteLogSpec(curves) {
  const { clip, ...axes } = logAxes(curves);
  return {
    ...axes,
    title: 'D(θh), log scale: the tails',
    series: seriesOf(curves),
    data: [ANGLES, ...curves.map((c) => clip(c.values))],
    filename: 'ndf-log',
    height: 260,
  };
}

/** The log plot with a measured slice: every curve over its own peak, so the tails compare at one width. */
function relativeLogSpec(curves, slice, name) {
  const label = `measured: ${name || 'unnamed'}, θd = 0 slice / peak`;
  const measured = { label, stroke: '#000000', width: 2.5, spanGaps: true };
  const relative = (c) => c.values.map((v) => (v / c.values[0] > 1e-5 ? v / c.values[0] : null));
  return {
    ...axis,
    title: 'D(θh) / D(0), log scale: the measured tail against the models at the fitted width',
    yLabel: 'D / D(0)',
    y: { min: 1e-5, max: 2, log: true },
    legend: true,
    series: [measured, ...seriesOf(curves)],
    data: [ANGLES, measuredOnAngles(slice), ...curves.map(relative)],
    filename: 'ndf-log',
    height: 260,
  };
}

const logSpec = (curves, state) =>
  state.measured.length ? relativeLogSpec(curves, state.measured, state.measuredName) : absoluteLogSpec(curves);

/** The slope maps of the chosen NDFs with an anisotropic form, and the conventions' pairs at the first one's α. */
function drawMaps(maps, curves, state) {
  const lobes = curves.filter((c) => c.aniso);
  const first = lobes[0];
  const pairs = first
    ? Object.fromEntries(ANISOTROPY_CONVENTIONS.map((k) => [k, anisotropicAlphas(first.p.alpha, state.anisotropy, k)]))
    : {};
  const text = describeAnisotropy(
    lobes.map((c) => c.aniso),
    state,
    { alpha: first?.p.alpha, of: first?.label },
    pairs,
  );
  maps.draw(
    lobes.map((c) => c.aniso),
    text,
  );
}

export function createNdfPlots(container, curves, state) {
  const linear = createPlot(container, linearSpec(curves));
  const log = createPlot(container, logSpec(curves, state));
  const tails = document.createElement('p');
  tails.className = 'tail-note';
  container.append(tails);
  const maps = createSlopeMaps(container);
  drawMaps(maps, curves, state);
  const drawLog = (next, nextState) => {
    log.setData(logSpec(next, nextState));
    tails.textContent = describeTails(tailsAt(next), nextState, TAIL_DEG);
  };
  drawLog(curves, state);
  return {
    drawLinear: (next) => linear.setData(linearSpec(next)),
    drawMaps: (next, nextState) => drawMaps(maps, next, nextState),
    drawLog,
    /** The log plot's measured curve as uPlot holds it: its label and the (θh, value) points drawn. */
    measuredCurve() {
      const u = log.uplot;
      if (!u) return null;
      const points = [...u.data[0]].map((x, i) => [x, u.data[1][i]]).filter(([, y]) => y != null);
      return { label: u.series[1].label, points };
    },
    dispose() {
      linear.dispose();
      log.dispose();
      tails.remove();
      maps.dispose();
    },
  };
}
