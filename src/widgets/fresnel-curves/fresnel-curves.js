// fresnel-curves: reflectance against angle of incidence for chosen materials, exact and Schlick
// overlaid, the talk's three zones shaded behind, and a second plot of Schlick's error.
import { createWidgetShell } from '../../core/widget-shell.js';
import { createStateGui } from '../../core/gui.js';
import { createPlot } from '../../core/plot.js';
import { CHANNEL_COLORS, SERIES_COLORS, ZONE_PALETTES, darken, withAlpha } from '../../core/palettes.js';
import { FRESNEL_ZONE_BOUNDS_DEG } from '../../math/zones.js';
import { METALS, NON_METALS } from '../../math/materials.js';
import { CHANNELS, angleGrid, curveSpecs, evaluateCurve } from './curve-data.js';

const MATERIAL_OPTIONS = Object.fromEntries([
  ...METALS.map((m) => [m.key, m.name]),
  ...NON_METALS.map((m) => [m.key, m.name]),
  ['custom', 'Custom dielectric (IOR below)'],
]);

export const schema = {
  materials: { type: 'set', options: MATERIAL_OPTIONS, default: ['copper', 'aluminum', 'glass-low', 'diamond'], label: 'Materials' },
  ior: { type: 'number', min: 1, max: 3, step: 0.01, default: 1.5, label: 'Custom IOR' },
  conductor: {
    type: 'enum',
    options: { 'f0-tint': 'Talk F0 + measured edge tint', measured: 'Measured n, k' },
    default: 'f0-tint',
    label: 'Metal n, k',
    hint: 'Talk F0 + edge tint: Gulbrandsen 2014 mapping, reproduces the table. Measured: published optical constants at 650/550/450 nm.',
  },
  schlick: { type: 'bool', default: true, label: 'Show Schlick' },
  zones: { type: 'bool', default: true, label: 'Shade zones' },
  palette: { type: 'enum', options: { talk: 'Talk', cb: 'Colour-blind safe' }, default: 'talk', label: 'Zone colours' },
};

const ABOUT =
  'Exact Fresnel reflectance (solid) against the angle between light and normal, with Schlick’s ' +
  'approximation (dashed) built from the same F(0°). Metals get one curve per channel (R, G, B). Try a metal ' +
  'with <em>Measured n, k</em>: its F(0°) no longer matches the talk’s table. Hover a plot to read values.';

const channelStroke = (spec, metalIndex, dielectricIndex) =>
  spec.metal ? darken(CHANNEL_COLORS[spec.channel], Math.min(metalIndex * 0.35, 0.7)) : SERIES_COLORS[dielectricIndex % SERIES_COLORS.length];

function buildSeries(state) {
  const angles = angleGrid();
  const specs = curveSpecs(state);
  const metalKeys = [...new Set(specs.filter((s) => s.metal).map((s) => s.key))];
  const dielectricKeys = specs.filter((s) => !s.metal).map((s) => s.key);
  const curves = specs.map((spec) => {
    const label = spec.metal ? `${spec.name} ${CHANNELS[spec.channel]}` : spec.name;
    const stroke = channelStroke(spec, metalKeys.indexOf(spec.key), dielectricKeys.indexOf(spec.key));
    return { spec, label, stroke, ...evaluateCurve(spec, angles) };
  });
  const zoneColors = ZONE_PALETTES[state.palette].colors;
  const [z1, z2] = FRESNEL_ZONE_BOUNDS_DEG;
  const bands = state.zones
    ? [
        { from: 0, to: z1, color: withAlpha(zoneColors[0], 0.16), label: 'barely changes' },
        { from: z1, to: z2, color: withAlpha(zoneColors[1], 0.22), label: 'changes somewhat' },
        { from: z2, to: 90, color: withAlpha(zoneColors[2], 0.16), label: '→ 1' },
      ]
    : [];
  return { angles, curves, bands };
}

const xAxis = { xLabel: 'Angle of incidence θ (degrees)', x: { min: 0, max: 90 }, xValues: (u, ticks) => ticks.map((t) => `${t}°`) };

function reflectanceSpec({ angles, curves, bands }, state) {
  const series = [];
  const data = [angles];
  for (const c of curves) {
    series.push({ label: `${c.label} exact`, stroke: c.stroke, width: 2 });
    data.push(c.exact);
    if (state.schlick) {
      series.push({ label: `${c.label} Schlick`, stroke: c.stroke, width: 1.5, dash: [6, 4] });
      data.push(c.schlick);
    }
  }
  return {
    title: 'Fresnel reflectance F(θ)', ...xAxis, yLabel: 'Reflectance (linear)', y: { min: 0, max: 1 },
    series, data, bands, filename: 'fresnel-reflectance', height: 320,
  };
}

function errorSpec({ angles, curves, bands }) {
  return {
    title: 'Schlick − exact', ...xAxis, yLabel: 'Error (reflectance)', y: null,
    series: curves.map((c) => ({ label: c.label, stroke: c.stroke, width: 1.5 })),
    data: [angles, ...curves.map((c) => c.error)], bands, filename: 'fresnel-schlick-error', height: 220,
  };
}

function renderSummary(el, curves) {
  el.replaceChildren();
  const table = document.createElement('table');
  table.className = 'data-table compact';
  table.innerHTML = '<caption>Per curve: exact F(0°), and Schlick’s largest error and where it sits</caption>' +
    '<thead><tr><th scope="col">Curve</th><th scope="col">n</th><th scope="col">k</th><th scope="col">F(0°)</th><th scope="col">max |Schlick − exact|</th><th scope="col">at θ</th></tr></thead>';
  const body = document.createElement('tbody');
  for (const c of curves) {
    const tr = document.createElement('tr');
    for (const text of [c.label, c.spec.eta.toFixed(3), c.spec.k.toFixed(3), c.f0.toFixed(3), Math.abs(c.maxError).toFixed(4), `${c.maxErrorAt.toFixed(2)}°`]) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.append(td);
    }
    body.append(tr);
  }
  table.append(body);
  el.append(table);
}

export function createFresnelCurves(container, initialState = {}, { onStateChange } = {}) {
  const shell = createWidgetShell(container, { name: 'fresnel-curves', schema, initialState, about: ABOUT });
  const plots = document.createElement('div');
  plots.className = 'plots';
  shell.view.append(plots);
  const summary = document.createElement('div');
  summary.className = 'summary';
  shell.view.append(summary);

  let data = buildSeries(shell.state);
  const reflectance = createPlot(plots, reflectanceSpec(data, shell.state));
  const error = createPlot(plots, errorSpec(data));
  renderSummary(summary, data.curves);
  const description = () =>
    `Fresnel reflectance against angle of incidence for ${data.curves.map((c) => c.label).join(', ') || 'no material'}.`;
  plots.setAttribute('aria-label', description());

  const refresh = () => {
    data = buildSeries(shell.state);
    reflectance.setData(reflectanceSpec(data, shell.state));
    error.setData(errorSpec(data));
    renderSummary(summary, data.curves);
    plots.setAttribute('aria-label', description());
  };

  const update = (partial) => {
    const changed = shell.apply(partial);
    if (!changed.length) return;
    gui.sync(shell.state);
    refresh();
    onStateChange?.(shell.state);
  };
  const gui = createStateGui(shell.controls, { schema, state: shell.state, onChange: update, title: 'Fresnel curves' });

  return {
    update,
    getState: () => shell.state,
    dispose() {
      gui.dispose();
      reflectance.dispose();
      error.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'fresnel-curves', schema, create: createFresnelCurves };
