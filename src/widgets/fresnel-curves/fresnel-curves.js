// fresnel-curves: reflectance against angle of incidence for chosen materials, exact and Schlick
// overlaid, the talk's three zones shaded behind, and a second plot of Schlick's error.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { SERIES_COLORS, ZONE_PALETTES, ZONE_PALETTE_FIELD, withAlpha } from '../../core/ui/palettes.js';
import { FRESNEL_ZONE_BOUNDS_DEG } from '../../math/zones.js';
import { CONDUCTOR_MODELS, METALS, NON_METALS } from '../../math/materials.js';
import { CHANNELS, angleGrid, curveSpecs, evaluateCurve } from './curve-data.js';

const MATERIAL_OPTIONS = Object.fromEntries([
  ...METALS.map((m) => [m.key, m.name]),
  ...NON_METALS.map((m) => [m.key, m.name]),
  ['custom', 'Custom dielectric (IOR below)'],
]);

export const schema = {
  materials: {
    type: 'set',
    options: MATERIAL_OPTIONS,
    default: ['copper', 'aluminum', 'glass-low', 'diamond'],
    label: 'Materials',
  },
  ior: { type: 'number', min: 1, max: 3, step: 0.01, default: 1.5, label: 'Custom IOR' },
  conductor: {
    type: 'enum',
    options: CONDUCTOR_MODELS,
    default: 'f0-tint',
    label: 'Metal n, k',
    hint:
      'Talk F0 + edge tint: Gulbrandsen 2014’s fitted n, k (a reparametrisation that reproduces the table, not ' +
      'optical constants). Measured: published optical constants at 650/550/450 nm.',
  },
  schlick: { type: 'bool', default: true, label: 'Show Schlick' },
  zones: { type: 'bool', default: true, label: 'Shade zones' },
  palette: ZONE_PALETTE_FIELD,
};

const ABOUT =
  'Exact Fresnel reflectance (solid) against the angle between light and normal, with Schlick’s ' +
  'approximation (dashed) built from the same F(0°). Metals get one curve per channel (R, G, B). Try a metal ' +
  'with <em>Measured n, k</em>: its F(0°) no longer matches the talk’s table. Hover a plot to read values.';

function buildSeries(state) {
  const angles = angleGrid();
  const specs = curveSpecs(state);
  const materialOrder = [...new Set(specs.map((s) => s.key))];
  const curves = specs.map((spec) => {
    const label = spec.metal ? `${spec.name} ${CHANNELS[spec.channel]}` : spec.name;
    const stroke = SERIES_COLORS[materialOrder.indexOf(spec.key) % SERIES_COLORS.length];
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

const xAxis = {
  xLabel: 'Angle of incidence θ (degrees)',
  x: { min: 0, max: 90 },
  xValues: (u, ticks) => ticks.map((t) => `${t}°`),
};

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
  const at = Math.round(4 / (angles[1] - angles[0]));
  const annotations = curves
    .filter((c) => c.spec.metal)
    .map((c, i) => ({ x: 2 + 5 * (i % 3), y: c.exact[at], text: CHANNELS[c.spec.channel], color: c.stroke }));
  return {
    title: 'Fresnel reflectance F(θ) — solid: exact, dashed: Schlick',
    ...xAxis,
    yLabel: 'Reflectance (linear)',
    y: { min: 0, max: 1 },
    series,
    data,
    bands,
    annotations,
    legend: false,
    filename: 'fresnel-reflectance',
    height: 320,
  };
}

function errorSpec({ angles, curves, bands }) {
  return {
    title: 'Schlick − exact',
    ...xAxis,
    yLabel: 'Error (reflectance)',
    y: null,
    series: curves.map((c) => ({ label: c.label, stroke: c.stroke, width: 1.5 })),
    data: [angles, ...curves.map((c) => c.error)],
    bands,
    legend: false,
    filename: 'fresnel-schlick-error',
    height: 220,
  };
}

const FITTED_NOTE =
  '† Fitted, not measured: Gulbrandsen 2014’s n, k, chosen to reproduce the talk’s F(0°) and the ' +
  'measured edge tint. They give the curve its shape but are not the metal’s optical constants (choose “Measured n, k” ' +
  'for those).';

/** The readout under the plots: per curve, the values at the angle under the pointer and Schlick's worst error. */
function renderReadout(el, { angles, curves }, index) {
  const i = index ?? angles.findIndex((a) => a >= 60);
  const theta = angles[i];
  const table = document.createElement('table');
  table.className = 'data-table compact readout';
  const fitted = curves.some((c) => c.spec.fitted);
  table.innerHTML =
    `<caption>Values at θ = ${theta.toFixed(2)}° (move the pointer over a plot), and where Schlick is worst` +
    `${fitted ? `. ${FITTED_NOTE}` : ''}</caption>` +
    '<thead><tr><th scope="col">Curve</th><th scope="col">n</th><th scope="col">k</th><th scope="col">F(0°)</th>' +
    `<th scope="col">exact at ${theta.toFixed(1)}°</th><th scope="col">Schlick</th><th scope="col">max |Schlick − exact|</th><th scope="col">at θ</th></tr></thead>`;
  const body = table.createTBody();
  for (const c of curves) {
    const tr = body.insertRow();
    const name = tr.insertCell();
    const sw = document.createElement('span');
    sw.className = 'swatch';
    sw.style.background = c.stroke;
    name.append(sw, ` ${c.label}`);
    const mark = c.spec.fitted ? '†' : '';
    for (const text of [
      `${c.spec.eta.toFixed(3)}${mark}`,
      `${c.spec.k.toFixed(3)}${mark}`,
      c.f0.toFixed(3),
      c.exact[i].toFixed(4),
      c.schlick[i].toFixed(4),
      Math.abs(c.maxError).toFixed(4),
      `${c.maxErrorAt.toFixed(2)}°`,
    ]) {
      tr.insertCell().textContent = text;
    }
  }
  el.replaceChildren(table);
}

const TERMS_USED = ['fresnelDielectric', 'fresnelConductor', 'fresnelSchlick']; // those with a GLSL twin

export function createFresnelCurves(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'fresnel-curves',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const plots = document.createElement('div');
  plots.className = 'plots';
  shell.view.append(plots);
  const summary = document.createElement('div');
  summary.className = 'summary';
  shell.view.append(summary);

  let data = buildSeries(shell.state);
  const onCursor = (index) => renderReadout(summary, data, index);
  const reflectance = createPlot(plots, reflectanceSpec(data, shell.state), { onCursor });
  const error = createPlot(plots, errorSpec(data), { onCursor });
  renderReadout(summary, data, null);
  // the plots describe themselves (core/plot.js); the summary says what a reader would look for
  const describe = () => {
    const worst = data.curves.reduce((a, c) => (!a || Math.abs(c.maxError) > Math.abs(a.maxError) ? c : a), null);
    shell.describe(
      `Fresnel reflectance against angle of incidence for ${data.curves.map((c) => `${c.label} (F(0°) ${c.f0.toFixed(3)})`).join(', ') || 'no material'}` +
        (worst
          ? `. Schlick's largest error: ${worst.maxError.toFixed(4)} for ${worst.label} at ${worst.maxErrorAt.toFixed(1)}°.`
          : '.'),
    );
  };
  describe();

  const refresh = () => {
    data = buildSeries(shell.state);
    reflectance.setData(reflectanceSpec(data, shell.state));
    error.setData(errorSpec(data));
    renderReadout(summary, data, null);
    describe();
  };

  const update = shell.connect({ title: 'Fresnel curves', onChanged: refresh, onStateChange });

  return {
    update,
    getState: () => shell.state,
    dispose() {
      reflectance.dispose();
      error.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'fresnel-curves', schema, create: createFresnelCurves, terms: TERMS_USED };
