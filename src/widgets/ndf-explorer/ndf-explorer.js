// ndf-explorer: the talk's five normal distribution functions at one matched width, on linear and log
// axes, their normalisation integrals measured live, and their highlights side by side on spheres.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { seriesStyle } from '../../core/ui/palettes.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { NDF_TERMS, microfacetBRDFAt, punctualRadiance } from '../../math/brdf.js';
import { matchNdfWidths } from '../../math/ndf-width.js';
import { ndfProjectedIntegral } from '../../math/integrate.js';
import { THETA_H_DEG } from '../measured-brdf/model.js';
import { DEG } from '../../math/angles.js';

export const NDFS = {
  blinnPhong: { name: 'Blinn-Phong', define: 'NDF_BLINN_PHONG' },
  beckmann: { name: 'Beckmann', define: 'NDF_BECKMANN' },
  ggx: { name: 'GGX (Trowbridge-Reitz)', define: 'NDF_GGX' },
  abc: { name: 'ABC', define: 'NDF_ABC' },
  sgd: { name: 'Shifted gamma (SGD)', define: 'NDF_SGD' },
};

export const schema = {
  hwhm: { type: 'number', min: 1, max: 40, step: 0.5, default: 8, label: 'Matched half width', unit: '°' },
  abcA2: { type: 'number', min: 0.5, max: 10, step: 0.1, default: 2.5, label: 'ABC shape a2' },
  sgdP: { type: 'number', min: 0, max: 1.9, step: 0.01, default: 0.64, label: 'SGD shape p' },
  ndfs: {
    type: 'set',
    options: Object.fromEntries(Object.entries(NDFS).map(([k, v]) => [k, v.name])),
    default: Object.keys(NDFS),
    label: 'Distributions',
  },
  lightTheta: { type: 'number', min: 0, max: 80, step: 1, default: 35, label: 'Light from view', unit: '°' },
  exposure: { type: 'number', min: 0.05, max: 50, step: 0.05, default: 1, label: 'Exposure' },
  // the NDF a measurement implies, as the measured-BRDF widget hands it over: D/D(0) at the 90 θh nodes of a
  // MERL table (0: missing or below 1e-5), and the name of its file
  measured: { type: 'samples', length: 90, min: 0, max: 1, default: [], label: 'Measured NDF slice' },
  measuredName: { type: 'text', maxLength: 80, default: '', label: 'Measured file' },
};

const ABOUT =
  'Each NDF is given the same half width at half maximum (the angle where D drops to half its peak), so the ' +
  'cores of the lobes match and only their shapes differ. The log plot shows the tails: GGX, ABC and SGD keep ' +
  'far more microfacets at large angles than Beckmann or Blinn-Phong, which is the halo around their highlights. ' +
  'Raise the exposure to see it. The spheres use F = 1 and V = 1 so that only D differs. The table integrates ' +
  'each D·(n·m) over the hemisphere: a density must give 1. Opened from the measured-BRDF widget (BRDF page), ' +
  'the log plot adds the NDF a measurement implies (black) and puts every curve over its own peak, so the ' +
  'measured tail is read against the five shapes at the fitted width.';

// every 0.25° and the θh nodes of a MERL table (where a measured slice has its values), in order
const ANGLES = Float64Array.from(new Set([...Array.from({ length: 361 }, (_, i) => i * 0.25), ...THETA_H_DEG])).sort();
const NODE_AT = new Map(Array.from(THETA_H_DEG, (deg, i) => [deg, i]));
/** The measured slice on ANGLES: its value at each node, null between nodes and where it is 0 (missing). */
const measuredOnAngles = (slice) =>
  Array.from(ANGLES, (deg) => (NODE_AT.has(deg) && slice[NODE_AT.get(deg)] > 0 ? slice[NODE_AT.get(deg)] : null));

/** The matched parameters of each NDF as the { alpha, exponent, a1, a2, p } object NDF_TERMS read. */
function parameters(state) {
  const m = matchNdfWidths(state.hwhm, { abcA2: state.abcA2, sgdP: state.sgdP });
  return {
    blinnPhong: { exponent: m.blinnPhong.exponent },
    beckmann: { alpha: m.beckmann.alpha },
    ggx: { alpha: m.ggx.alpha },
    abc: { a1: m.abc.a1, a2: m.abc.a2 },
    sgd: { alpha: m.sgd.alpha, p: m.sgd.p },
  };
}

const describeParams = (key, p) =>
  key === 'blinnPhong'
    ? `exponent ${p.exponent.toFixed(1)}`
    : key === 'abc'
      ? `a1 ${p.a1.toFixed(2)}, a2 ${p.a2.toFixed(2)}`
      : key === 'sgd'
        ? `α ${p.alpha.toFixed(4)}, p ${p.p.toFixed(2)}`
        : `α ${p.alpha.toFixed(4)}`;

function curves(state) {
  const params = parameters(state);
  return state.ndfs.map((key) => {
    const p = params[key];
    const D = (c) => NDF_TERMS[key](c, p);
    return {
      key,
      p,
      label: NDFS[key].name,
      ...seriesStyle(Object.keys(NDFS).indexOf(key)),
      values: ANGLES.map((deg) => D(Math.cos(deg * DEG))),
      integral: ndfProjectedIntegral(D),
    };
  });
}

const axis = {
  xLabel: 'Angle of the microfacet normal from n, θh (degrees)',
  x: { min: 0, max: 90 },
  xValues: (u, t) => t.map((v) => `${v}°`),
};

/** The log plot with a measured slice: every curve over its own peak, so the tails compare at one width. */
function relativeLogSpec(data, slice, name) {
  const label = `measured: ${name || 'unnamed'}, θd = 0 slice / peak`;
  const measured = { label, stroke: '#000000', width: 2.5, spanGaps: true };
  const relative = (c) => c.values.map((v) => (v / c.values[0] > 1e-5 ? v / c.values[0] : null));
  return {
    ...axis,
    title: 'D(θh) / D(0), log scale: the measured tail against the models at the fitted width',
    yLabel: 'D / D(0)',
    y: { min: 1e-5, max: 2, log: true },
    legend: true,
    series: [measured, ...data.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash }))],
    data: [ANGLES, measuredOnAngles(slice), ...data.map(relative)],
    filename: 'ndf-log',
    height: 260,
  };
}

const TERMS_USED = ['ndfBlinnPhong', 'ndfBeckmann', 'ndfGGX', 'ndfABC', 'ndfSGD', 'microfacetBRDF'];

export function createNdfExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'ndf-explorer',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const plots = document.createElement('div');
  shell.view.append(plots);
  const table = document.createElement('div');

  let data = curves(shell.state);
  const linearSpec = () => ({
    ...axis,
    title: 'D(θh), linear',
    yLabel: 'D (1/sr)',
    y: null,
    legend: true,
    series: data.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash })),
    data: [ANGLES, ...data.map((c) => c.values)],
    filename: 'ndf-linear',
    height: 260,
  });
  const logSpec = () => {
    const slice = shell.state.measured;
    if (slice.length) return relativeLogSpec(data, slice, shell.state.measuredName);
    const peak = Math.max(...data.map((c) => c.values[0]), 1e-3);
    return {
      ...axis,
      title: 'D(θh), log scale: the tails',
      yLabel: 'D (1/sr)',
      y: { min: peak * 1e-7, max: peak * 2, log: true },
      legend: false,
      series: data.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash })),
      data: [ANGLES, ...data.map((c) => c.values.map((v) => (v > peak * 1e-7 ? v : null)))],
      filename: 'ndf-log',
      height: 260,
    };
  };
  const linear = createPlot(plots, linearSpec());
  const log = createPlot(plots, logSpec());
  const spheres = createSphereGrid(shell.view, { label: 'NDF highlights on spheres' });
  shell.view.append(table);

  const renderTable = () => {
    table.innerHTML =
      '<table class="data-table compact"><caption>Normalisation, measured: ∫ D(m)(n·m) dω over the hemisphere (Simpson, 4000 intervals)</caption>' +
      '<thead><tr><th>NDF</th><th>parameters at this width</th><th>∫ D (n·m) dω</th><th>|error|</th><th>D(0°)</th></tr></thead><tbody>' +
      data
        .map(
          (c) =>
            `<tr><td><span class="swatch" style="background:${c.stroke}"></span> ${c.label}</td><td>${describeParams(c.key, c.p)}</td>` +
            `<td>${c.integral.toFixed(7)}</td><td>${Math.abs(c.integral - 1).toExponential(1)}</td><td>${c.values[0].toPrecision(4)}</td></tr>`,
        )
        .join('') +
      '</tbody></table>';
  };
  const renderSpheres = () => {
    const s = shell.state;
    const l = lightDirFromAngles(s.lightTheta, 135);
    spheres.setCells(
      data.map((c) => ({
        label: c.label.split(' (')[0],
        defines: { [NDFS[c.key].define]: true, VIS_IMPLICIT: true, F_ONE: true },
        uniforms: {
          uLightDir: l,
          uExposure: s.exposure,
          uAlpha: c.p.alpha ?? 0.3,
          uExponent: c.p.exponent ?? 1,
          uA1: c.p.a1 ?? 1,
          uA2: c.p.a2 ?? 1,
          uSgdP: c.p.p ?? 0,
        },
        probe: (a) => [
          ['D(n·h)', `${NDF_TERMS[c.key](a.nh, c.p).toPrecision(4)} /sr`],
          [
            'radiance π·D/4·(n·l)',
            punctualRadiance(microfacetBRDFAt(a, { F: 'one', D: c.key, V: 'implicit', ...c.p }), a.nl, 1).toPrecision(
              4,
            ),
          ],
        ],
      })),
    );
    shell.describe(
      `Spheres lit by one small light ${s.lightTheta}° from the view, exposure ${s.exposure}, F = 1 and V = 1, one per NDF at a half width of ${s.hwhm}°: ` +
        `${data.map((c) => `${c.label} (${describeParams(c.key, c.p)}, peak D ${c.values[0].toPrecision(3)} /sr)`).join(', ') || 'none chosen'}.`,
      spheres.canvas,
    );
  };
  renderTable();
  renderSpheres();

  const onChanged = (changed) => {
    if (changed.some((k) => ['hwhm', 'abcA2', 'sgdP', 'ndfs'].includes(k))) {
      data = curves(shell.state);
      linear.setData(linearSpec());
      renderTable();
    }
    const logKeys = ['hwhm', 'abcA2', 'sgdP', 'ndfs', 'measured', 'measuredName'];
    if (changed.some((k) => logKeys.includes(k))) log.setData(logSpec());
    renderSpheres();
  };
  const update = shell.connect({ title: 'NDF explorer', onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getIntegrals: () => Object.fromEntries(data.map((c) => [c.key, c.integral])),
    /** The log plot's measured curve as uPlot holds it: its label and the (θh, value) points drawn. */
    getMeasuredCurve() {
      const u = log.uplot;
      if (!shell.state.measured.length || !u) return null;
      const points = [...u.data[0]].map((x, i) => [x, u.data[1][i]]).filter(([, y]) => y != null);
      return { label: u.series[1].label, points };
    },
    dispose() {
      linear.dispose();
      log.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'ndf-explorer', schema, create: createNdfExplorer, terms: TERMS_USED };
