// diffuse-explorer: Lambert, the diffuse-specular trade-off (Fresnel-weighted Lambert, Ashikhmin-Shirley) and
// Oren-Nayar (full and qualitative), on a row of GPU-shaded spheres under a light the user moves, and as plots:
// the brightness across a sphere (the rough "full moon" flattening), radiance as the light sweeps past a fixed
// view, and the light returned by specular plus diffuse against the view angle.
import { SIGMA_HINT, sigmaText } from '../../core/ui/sigma-range.js';
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { SERIES_COLORS } from '../../core/ui/palettes.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { createLightPad } from './light-pad.js';
import {
  MODELS,
  PROFILE_XS,
  SWEEP_XS,
  TRADE_XS,
  cosPhiDiff,
  lightSweep,
  paramsOf,
  profile,
  radianceAt,
  tradeOff,
} from './diffuse-curves.js';

const MODEL_KEYS = Object.keys(MODELS);

export const schema = {
  models: {
    type: 'set',
    options: Object.fromEntries(MODEL_KEYS.map((k) => [k, MODELS[k].name])),
    default: MODEL_KEYS,
    label: 'Diffuse models',
  },
  sigma: {
    type: 'number',
    min: 0,
    max: 90,
    step: 1,
    default: 40,
    label: 'Oren–Nayar roughness σ',
    unit: '°',
    hint: SIGMA_HINT,
  },
  cdiff: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.8, label: 'Diffuse colour c_diff' },
  f0: { type: 'number', min: 0, max: 1, step: 0.01, default: 0.04, label: 'Specular F0 (trade-off)' },
  lightTheta: { type: 'number', min: 0, max: 180, step: 0.5, default: 0, label: 'Light from view', unit: '°' },
  lightPhi: { type: 'number', min: -180, max: 180, step: 0.5, default: 0, label: 'Light around view', unit: '°' },
  viewTheta: { type: 'number', min: 0, max: 85, step: 1, default: 45, label: 'View angle (sweep plot)', unit: '°' },
  exposure: { type: 'number', min: 0.1, max: 4, step: 0.05, default: 1, label: 'Sphere exposure' },
};

const ABOUT =
  'Every sphere has a diffuse term only, lit by one punctual light (L = π f c_light (n·l), c_light = 1). ' +
  'Lambert’s f is a constant, so its brightness is just the cosine: bright where the surface faces the light, ' +
  'dark towards the terminator. The two trade-off models give the specular term first claim on the light, so ' +
  'they darken near the silhouette, where Fresnel reflection takes nearly everything; F0 sets how much they ' +
  'give up. Oren–Nayar models a surface of V-shaped grooves whose slopes spread by σ: grooves facing the viewer ' +
  'are also the lit ones when the light is behind the viewer, so the rim stays bright and the disc looks flat, ' +
  'like the full moon. Put the light at the centre of the pad, raise σ and compare the profiles; at σ = 0 both ' +
  'Oren–Nayar forms are exactly Lambert. σ is the spread of the facet tilt angle: beyond about 45° a Gaussian ' +
  'that wide would tilt over 4.6% of the facets past 90°, so the slider’s upper half (to 90°) extrapolates the ' +
  'model, and the plots say so. The last plot adds a smooth specular F(θv) to each diffuse albedo: above 1, the ' +
  'pair reflects more light than arrives. Fresnel-weighted Lambert is not normalised: head-on it returns ' +
  '(1 − F0)²·20/21 of c_diff (0.878 at F0 = 0.04).';

const TERMS_USED = [
  'diffuseLambert',
  'diffuseFresnelWeighted',
  'diffuseAshikhminShirley',
  'diffuseOrenNayar',
  'diffuseOrenNayarQualitative',
  'fresnelSchlick',
];

const colorOf = (key) => SERIES_COLORS[MODEL_KEYS.indexOf(key) % SERIES_COLORS.length];
const degValues = (u, ticks) => ticks.map((t) => `${t}°`);
/** Where the flatness table reads the profile: 90% of the way to the rim, on the light's side. */
const RIM = 0.9;

export function createDiffuseExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'diffuse-explorer',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const lightDir = () => lightDirFromAngles(shell.state.lightTheta, shell.state.lightPhi);
  let update = () => {};
  // the spheres, their probe readout and, beside it, the pad that moves their light
  const stage = document.createElement('div');
  stage.className = 'diffuse-stage';
  shell.view.append(stage);
  const spheres = createSphereGrid(stage, { label: 'Diffuse models on spheres' });
  const pad = createLightPad(stage, {
    label: 'Light direction for the spheres and the profile plot',
    get: () => shell.state,
    set: (partial) => update(partial),
  });
  const plots = document.createElement('div');
  const table = document.createElement('div');
  shell.view.append(plots);

  const series = () => shell.state.models.map((k) => ({ label: MODELS[k].name, stroke: colorOf(k) }));
  let profileData = profile(shell.state, lightDir());
  let sweepData = lightSweep(shell.state);
  let tradeData = tradeOff(shell.state);

  const profileSpec = () => ({
    title: `Brightness across the sphere, through the side the light is on (${sigmaText(shell.state.sigma)})`,
    xLabel: 'Diameter position (radii, + = light side)',
    yLabel: 'Lo / c_light',
    x: { min: -1, max: 1 },
    y: null,
    series: series(),
    data: [PROFILE_XS, ...profileData],
    filename: 'diffuse-profile',
    height: 260,
  });
  const sweepSpec = () => {
    const tv = shell.state.viewTheta;
    return {
      title: `Radiance of a flat patch seen from θv = ${tv}°, the light sweeping through the plane of n and v (${sigmaText(shell.state.sigma)})`,
      xLabel: 'Light angle θl (degrees, + = viewer’s side)',
      yLabel: 'Lo / c_light',
      x: { min: -90, max: 90 },
      y: null,
      xValues: degValues,
      series: series(),
      data: [SWEEP_XS, ...sweepData],
      bands: [
        { from: tv - 0.6, to: tv + 0.6, color: '#e69f0055', label: 'l = v' },
        { from: -tv - 0.6, to: -tv + 0.6, color: '#56b4e955', label: 'mirror' },
      ],
      filename: 'diffuse-light-sweep',
      height: 260,
    };
  };
  const tradeSpec = () => ({
    title: `Light sent back: smooth specular F(θv) (F0 = ${shell.state.f0}) plus each diffuse albedo (c_diff = ${shell.state.cdiff})`,
    xLabel: 'View angle θv (degrees)',
    yLabel: 'returned / incident',
    x: { min: 0, max: 90 },
    y: { min: 0, max: 2 },
    xValues: degValues,
    series: [
      ...series().map((s) => ({ ...s, label: `F + ${s.label}` })),
      { label: 'F alone (specular)', stroke: '#777777', dash: [6, 4] },
      { label: 'all the incident light', stroke: '#000000', dash: [2, 3], width: 1 },
    ],
    data: [TRADE_XS, ...tradeData.totals, tradeData.specular, TRADE_XS.map(() => 1)],
    filename: 'diffuse-specular-tradeoff',
    height: 260,
  });
  const profilePlot = createPlot(plots, profileSpec());
  plots.append(table);
  const sweepPlot = createPlot(plots, sweepSpec());
  const tradePlot = createPlot(plots, tradeSpec());

  const renderTable = () => {
    const centre = PROFILE_XS.indexOf(0);
    const rim = PROFILE_XS.findIndex((x) => Math.abs(x - RIM) < 1e-9);
    const rows = shell.state.models.map((k, i) => {
      const [c, r] = [profileData[i][centre], profileData[i][rim]];
      return `<tr><td><span class="swatch" style="background:${colorOf(k)}"></span> ${MODELS[k].name}</td><td>${c.toFixed(4)}</td><td>${r.toFixed(4)}</td><td>${c > 1e-9 ? (r / c).toFixed(3) : '—'}</td></tr>`;
    });
    table.innerHTML =
      `<table class="data-table compact"><caption>How flat the disc looks: Lo / c_light at the centre and ${RIM * 100}% of the way to the rim (light’s side)</caption>` +
      '<thead><tr><th>Model</th><th>centre</th><th>at 0.9 R</th><th>rim / centre</th></tr></thead><tbody>' +
      rows.join('') +
      '</tbody></table>';
  };
  const renderSpheres = () => {
    const s = shell.state;
    const p = paramsOf(s);
    const l = lightDir();
    spheres.setCells(
      s.models.map((k) => ({
        label: MODELS[k].short,
        defines: { SPECULAR_OFF: true, [MODELS[k].define]: true },
        uniforms: { uLightDir: l, uExposure: s.exposure, uDiffuse: s.cdiff, uF0: s.f0, uSigma: p.sigma },
        probe: (a, n) => {
          const f = MODELS[k].f(a.nl, a.nv, cosPhiDiff(n, l, [0, 0, 1]), p);
          return [
            ['f (1/sr)', f.toFixed(5)],
            ['f / Lambert', s.cdiff > 0 ? (f / (s.cdiff / Math.PI)).toFixed(4) : '—'],
            ['Lo / c_light', radianceAt(k, n, l, [0, 0, 1], p).toFixed(4)],
          ];
        },
      })),
    );
    shell.describe(
      `Spheres with a diffuse term only (c_diff ${s.cdiff}, F0 ${s.f0}, ${sigmaText(s.sigma)}), light ${s.lightTheta}° from the view: ${s.models.map((k) => MODELS[k].name).join(', ')}.`,
      spheres.canvas,
    );
  };
  renderTable();
  renderSpheres();

  const onChanged = (changed) => {
    const touches = (...keys) => changed.some((k) => keys.includes(k));
    if (touches('models', 'sigma', 'cdiff', 'f0', 'lightTheta', 'lightPhi')) {
      profileData = profile(shell.state, lightDir());
      profilePlot.setData(profileSpec());
      renderTable();
    }
    if (touches('models', 'sigma', 'cdiff', 'f0', 'viewTheta')) {
      sweepData = lightSweep(shell.state);
      sweepPlot.setData(sweepSpec());
    }
    if (touches('models', 'sigma', 'cdiff', 'f0')) {
      tradeData = tradeOff(shell.state);
      tradePlot.setData(tradeSpec());
    }
    if (touches('lightTheta', 'lightPhi')) pad.draw();
    renderSpheres();
  };
  update = shell.connect({ title: 'Diffuse explorer', onChanged, onStateChange });

  const plotted = (plot) => plot.uplot.data.map((col) => Array.from(col));
  return {
    update,
    getState: () => shell.state,
    /** The data each plot draws, [xs, ...series], as uPlot holds it. */
    getPlots: () => ({ profile: plotted(profilePlot), sweep: plotted(sweepPlot), tradeOff: plotted(tradePlot) }),
    dispose() {
      pad.dispose();
      profilePlot.dispose();
      sweepPlot.dispose();
      tradePlot.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'diffuse-explorer', schema, create: createDiffuseExplorer, terms: TERMS_USED };
