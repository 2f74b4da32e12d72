// visibility-explorer: every geometry/visibility term of the talk against angle at one roughness, how far
// each is from height-correlated Smith, and what that does to a sphere's edges.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { seriesStyle } from '../../core/ui/palettes.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { VISIBILITY_TERMS, brdfAngles } from '../../math/brdf.js';
import { DEG } from '../../math/angles.js';

export const TERMS = {
  implicit: { name: 'Implicit (V = 1)', define: 'VIS_IMPLICIT' },
  cookTorrance: { name: 'Cook-Torrance', define: 'VIS_COOK_TORRANCE' },
  kelemen: { name: 'Kelemen 1/(l·h)²', define: 'VIS_KELEMEN' },
  smithGGXSeparable: { name: 'Smith GGX, separable', define: 'VIS_SMITH_GGX_SEPARABLE' },
  smithGGXCorrelated: { name: 'Smith GGX, height-correlated', define: 'VIS_SMITH_GGX_CORRELATED' },
  smithGGXCorrelatedFast: { name: 'Hammon 2017 approx.', define: 'VIS_SMITH_GGX_CORRELATED_FAST' },
  schlickGGX: { name: 'Schlick-GGX (k = α/2)', define: 'VIS_SCHLICK_GGX' },
  smithBeckmannSeparable: { name: 'Smith Beckmann, separable', define: 'VIS_SMITH_BECKMANN_SEPARABLE' },
};
const REFERENCE = 'smithGGXCorrelated';

export const schema = {
  alpha: { type: 'number', min: 0.01, max: 1, step: 0.01, default: 0.5, label: 'Roughness α' },
  config: {
    type: 'enum',
    options: { mirror: 'l, v mirrored about n (h = n)', 'view-fixed': 'View fixed, light sweeps' },
    default: 'view-fixed',
    label: 'Directions',
  },
  viewTheta: { type: 'number', min: 0, max: 85, step: 1, default: 60, label: 'View angle (view fixed)', unit: '°' },
  terms: {
    type: 'set',
    options: Object.fromEntries(Object.entries(TERMS).map(([k, v]) => [k, v.name])),
    default: [
      'implicit',
      'cookTorrance',
      'kelemen',
      'smithGGXSeparable',
      'smithGGXCorrelated',
      'smithGGXCorrelatedFast',
      'schlickGGX',
    ],
    label: 'Terms',
  },
  lightTheta: { type: 'number', min: 0, max: 85, step: 1, default: 30, label: 'Sphere light from view', unit: '°' },
  exposure: { type: 'number', min: 0.1, max: 20, step: 0.1, default: 1.5, label: 'Sphere exposure' },
};

const ABOUT =
  'The plots show G = V·(n·l)(n·v), the share of microfacets that are neither shadowed nor masked, so that ' +
  'all terms share one scale. The implicit term is G = (n·l)(n·v): it falls too soon and is the same at every ' +
  'roughness. Change α and watch which curves move. The error plot measures each term against ' +
  'height-correlated Smith. With l and v mirrored about n, h = n and both Cook-Torrance and Kelemen give G = 1 ' +
  'exactly. On the spheres (GGX D, F = 1) the differences show at the silhouettes, where the ' +
  'angles are grazing.';

const ANGLES = Float64Array.from({ length: 357 }, (_, i) => i * 0.25); // 0..89°

function directions(state, deg) {
  const t = deg * DEG;
  if (state.config === 'mirror') return { l: [Math.sin(t), 0, Math.cos(t)], v: [-Math.sin(t), 0, Math.cos(t)] };
  const tv = state.viewTheta * DEG;
  return { l: [Math.sin(t), 0, Math.cos(t)], v: [-Math.sin(tv), 0, Math.cos(tv)] };
}

function curves(state) {
  const params = { alpha: state.alpha };
  const evalTerm = (key) =>
    ANGLES.map((deg) => {
      const { l, v } = directions(state, deg);
      const a = brdfAngles(l, v);
      return VISIBILITY_TERMS[key](a, params) * a.nl * a.nv;
    });
  const reference = evalTerm(REFERENCE);
  return state.terms.map((key) => {
    const G = evalTerm(key);
    const error = G.map((g, i) => (reference[i] > 1e-9 ? (100 * (g - reference[i])) / reference[i] : null));
    const within = error.filter((e, i) => e !== null && ANGLES[i] <= 80);
    return {
      key,
      label: TERMS[key].name,
      ...seriesStyle(Object.keys(TERMS).indexOf(key)),
      G,
      error,
      worst: Math.max(...within.map(Math.abs)),
    };
  });
}

const TERMS_USED = [
  'visibilityImplicit',
  'visibilityCookTorrance',
  'visibilityKelemen',
  'visibilitySmithGGXSeparable',
  'visibilitySmithGGXCorrelated',
  'visibilitySmithGGXCorrelatedFast',
  'visibilitySchlickGGX',
  'visibilitySmithBeckmannSeparable',
  'microfacetBRDF',
];

export function createVisibilityExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'visibility-explorer',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const plots = document.createElement('div');
  shell.view.append(plots);
  let data = curves(shell.state);
  const xLabel = () =>
    shell.state.config === 'mirror'
      ? 'Angle of l and of v from n (degrees)'
      : `Light angle θl, view fixed at ${shell.state.viewTheta}° (degrees)`;
  const gSpec = () => ({
    title: `G = V·(n·l)(n·v) at α = ${shell.state.alpha}`,
    xLabel: xLabel(),
    yLabel: 'G',
    x: { min: 0, max: 90 },
    y: { min: 0, max: 1.05 },
    xValues: (u, t) => t.map((v) => `${v}°`),
    series: data.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash })),
    data: [ANGLES, ...data.map((c) => c.G)],
    filename: 'visibility-G',
    height: 280,
  });
  const errSpec = () => ({
    title: 'Difference from height-correlated Smith (%)',
    xLabel: xLabel(),
    yLabel: 'error (%)',
    x: { min: 0, max: 90 },
    y: { min: -100, max: 100 },
    xValues: (u, t) => t.map((v) => `${v}°`),
    legend: false,
    series: data.map((c) => ({ label: c.label, stroke: c.stroke, dash: c.dash })),
    data: [ANGLES, ...data.map((c) => c.error)],
    filename: 'visibility-error',
    height: 220,
  });
  const gPlot = createPlot(plots, gSpec());
  const errPlot = createPlot(plots, errSpec());
  const table = document.createElement('div');
  const spheres = createSphereGrid(shell.view, { label: 'Visibility terms on spheres' });
  shell.view.append(table);

  const renderTable = () => {
    table.innerHTML =
      '<table class="data-table compact"><caption>Largest difference from height-correlated Smith up to 80°, in these directions</caption>' +
      '<thead><tr><th>Term</th><th>max |error|</th></tr></thead><tbody>' +
      data
        .map(
          (c) =>
            `<tr><td><span class="swatch" style="background:${c.stroke}"></span> ${c.label}</td><td>${c.worst.toFixed(1)}%</td></tr>`,
        )
        .join('') +
      '</tbody></table>';
  };
  const renderSpheres = () => {
    const s = shell.state;
    spheres.setCells(
      data.map((c) => ({
        label: c.label.split(' (')[0].replace(', height-correlated', ' corr.').replace(', separable', ' sep.'),
        defines: { [TERMS[c.key].define]: true, NDF_GGX: true, F_ONE: true },
        uniforms: { uLightDir: lightDirFromAngles(s.lightTheta, 135), uExposure: s.exposure, uAlpha: s.alpha },
        probe: (a) => {
          const V = VISIBILITY_TERMS[c.key](a, { alpha: s.alpha });
          return [
            ['V', V.toPrecision(4)],
            ['G = V (n·l)(n·v)', (V * Math.max(a.nl, 0) * Math.max(a.nv, 0)).toFixed(4)],
            ['V / V Smith corr.', (V / VISIBILITY_TERMS[REFERENCE](a, { alpha: s.alpha })).toFixed(4)],
          ];
        },
      })),
    );
    shell.describe(
      `Spheres with GGX D at α ${s.alpha} and F = 1, light ${s.lightTheta}° from the view, exposure ${s.exposure}, one per visibility term. ` +
        `Largest difference from height-correlated Smith up to 80° (${s.config === 'mirror' ? 'l and v mirrored' : `view at ${s.viewTheta}°`}): ` +
        `${data.map((c) => `${c.label} ${c.worst.toFixed(1)}%`).join(', ') || 'no term chosen'}.`,
      spheres.canvas,
    );
  };
  renderTable();
  renderSpheres();

  const onChanged = (changed) => {
    if (changed.some((k) => ['alpha', 'config', 'viewTheta', 'terms'].includes(k))) {
      data = curves(shell.state);
      gPlot.setData(gSpec());
      errPlot.setData(errSpec());
      renderTable();
    }
    renderSpheres();
  };
  const update = shell.connect({ title: 'Visibility explorer', onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getWorstErrors: () => Object.fromEntries(data.map((c) => [c.key, c.worst])),
    dispose() {
      gPlot.dispose();
      errPlot.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'visibility-explorer', schema, create: createVisibilityExplorer, terms: TERMS_USED };
