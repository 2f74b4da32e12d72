// energy: the white furnace. With F = 1 a microfacet BRDF should send back all the light it receives, but
// the model drops every ray that a second microfacet blocks. Directional albedo E(mu) against angle for a
// sweep of roughness, the energy lost 1 - E, and spheres in a uniform white environment, each pixel reading
// E(n·v) from the split-sum table (the same float64 quadrature, bilinear on the GPU). A compensation switch puts
// the lost energy back (Kulla & Conty 2017, Turquin 2019), and a coloured metal's albedo is set beside the walk.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { seriesStyle } from '../../core/ui/palettes.js';
import { createDfgTexture } from '../../lab/environment-maps.js';
import { createAlbedoTableTexture, albedoTableOnce } from '../../core/gpu/albedo-table-texture.js';
import { albedoGGX, averageAlbedo } from '../../math/integrate.js';
import { specularAlbedoFromTable } from '../../math/albedo-table.js';
import { METALS } from '../../math/materials.js';
import { createMetalView } from './metal-view.js';
import { DEG } from '../../math/angles.js';

export const schema = {
  alphas: {
    type: 'set',
    // '1.0', not '1': an integer-like key would be listed first
    options: { 0.05: 'α 0.05', 0.25: 'α 0.25', 0.5: 'α 0.5', 0.75: 'α 0.75', '1.0': 'α 1' },
    default: ['0.05', '0.25', '0.5', '0.75', '1.0'],
    label: 'Roughness sweep',
  },
  compensation: {
    type: 'enum',
    options: { none: 'None', kullaConty: 'Kulla–Conty 2017', turquin: 'Turquin 2019' },
    default: 'none',
    label: 'Energy compensation',
  },
  metal: {
    type: 'enum',
    options: Object.fromEntries(METALS.map((m) => [m.key, m.name])),
    default: 'gold',
    label: 'Coloured metal',
  },
  metalAlpha: { type: 'number', min: 0.05, max: 1, step: 0.05, default: 0.8, label: 'Metal roughness α' },
};

// the spheres' shader variant per compensation
const FURNACE_DEFINES = {
  none: { FURNACE: true },
  kullaConty: { FURNACE: true, FURNACE_KULLA_CONTY: true, ALBEDO_TABLE_GGX: true },
  turquin: { FURNACE: true, FURNACE_TURQUIN: true, ALBEDO_TABLE_GGX: true },
};

const ABOUT =
  'In a uniform white environment a surface that loses no energy looks exactly as bright as its ' +
  'surroundings: it disappears. These spheres use GGX with height-correlated Smith and F = 1. Smooth ones ' +
  'nearly vanish; rough ones turn grey, most of all at the centre, because light blocked by one microfacet is ' +
  'simply dropped instead of bouncing on (the talk’s multiple-bounce slide). The plots give E(μ) = ∫ f (n·l) dω ' +
  'by deterministic quadrature over the microfacet normals, and each sphere pixel reads E(n·v) from a texture ' +
  'precomputed with it; the table below gives E head-on and its cosine-weighted average over all directions. ' +
  'Energy compensation puts the dropped light back: Kulla & Conty (2017) add a second, nearly diffuse lobe, ' +
  'Turquin (2019) scales the first; with F = 1 both make every sphere vanish. Below, a coloured metal shows what ' +
  'they cost and buy against the random walk on the microsurface (Heitz et al. 2016), the light followed from ' +
  'facet to facet.';

const ANGLES = Float64Array.from({ length: 90 }, (_, i) => i + 0.5); // view angles 0.5°..89.5°

// the plots' curves: 24 Gauss-Legendre nodes per piece, within 2e-5 of the adaptive quadrature (unit-tested)
const PLOT_QUADRATURE = { nodes: 24 };

function sweep(state) {
  return state.alphas
    .map(Number)
    .sort((a, b) => a - b)
    .map((alpha, i) => {
      const E = ANGLES.map((deg) => albedoGGX(Math.cos(deg * DEG), alpha, {}, PLOT_QUADRATURE));
      const avg = averageAlbedo((mu) => albedoGGX(mu, alpha));
      return { alpha, E, loss: E.map((e) => 1 - e), avg, ...seriesStyle(i), atNormal: albedoGGX(1, alpha) };
    });
}

const TERMS_USED = [
  'dfgTableUv',
  'visibilitySmithGGXCorrelated',
  'ndfGGX',
  'specularAlbedoKullaConty',
  'specularAlbedoTurquin',
];

export function createEnergy(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'energy',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const plots = document.createElement('div');
  shell.view.append(plots);
  const spheres = createSphereGrid(shell.view, { label: 'Spheres in a white furnace', background: '#ffffff' });
  const table = document.createElement('div');
  shell.view.append(table);
  const metalNow = () => metalView.update(shell.state.metal, shell.state.metalAlpha);
  const metalView = createMetalView(shell.view, () => describe(metalNow())); // again when its walk arrives
  const dfg = createDfgTexture(); // GGX, height-correlated Smith: scale + bias is E
  let lossTable = null; // the albedo-loss table, made when a compensation is first chosen
  let data = sweep(shell.state);

  const base = { xLabel: 'View angle θv (degrees)', x: { min: 0, max: 90 }, xValues: (u, t) => t.map((v) => `${v}°`) };
  const eSpec = () => ({
    ...base,
    title: 'Directional albedo E(θv), F = 1',
    yLabel: 'E',
    y: { min: 0, max: 1.02 },
    series: data.map((d) => ({ label: `α = ${d.alpha}`, stroke: d.stroke, dash: d.dash })),
    data: [ANGLES, ...data.map((d) => d.E)],
    filename: 'albedo',
    height: 260,
  });
  const lossSpec = () => ({
    ...base,
    title: 'Energy lost to ignoring multiple bounces, 1 − E',
    yLabel: '1 − E',
    y: { min: 0, max: 0.8 },
    legend: false,
    series: data.map((d) => ({ label: `α = ${d.alpha}`, stroke: d.stroke, dash: d.dash })),
    data: [ANGLES, ...data.map((d) => d.loss)],
    filename: 'energy-loss',
    height: 220,
  });
  const ePlot = createPlot(plots, eSpec());
  const lossPlot = createPlot(plots, lossSpec());

  /** The text for screen readers. */
  const describe = (metal) => {
    const comp = shell.state.compensation;
    const compensated =
      comp === 'none' ? '' : ` With ${schema.compensation.options[comp]} every sphere reflects all of it and vanishes.`;
    shell.describe(
      'Spheres in a uniform white environment (F = 1); a sphere that loses no energy vanishes into it.' +
        compensated +
        ' ' +
        `${data.map((d) => `α ${d.alpha}: albedo ${d.atNormal.toFixed(3)} head-on, ${d.avg.toFixed(3)} on average, ${((1 - d.avg) * 100).toFixed(1)}% lost`).join('; ') || 'No roughness chosen'}. ` +
        `${metal.metal.name} at α ${metal.alpha} head-on: single scattering ${metal.curves.none[0].map((x) => x.toFixed(2)).join(', ')}, ` +
        `random walk ${metal.walk ? metal.walk[0].albedo.map((x) => x.toFixed(2)).join(', ') : 'still running'} (R, G, B).`,
      spheres.canvas,
    );
  };
  const render = () => {
    table.innerHTML =
      '<table class="data-table compact"><caption>Albedo with F = 1 (GGX, height-correlated Smith)</caption>' +
      '<thead><tr><th>α</th><th>E at normal incidence</th><th>E averaged over the hemisphere</th><th>energy lost on average</th></tr></thead><tbody>' +
      data
        .map(
          (d) =>
            `<tr><td><span class="swatch" style="background:${d.stroke}"></span> ${d.alpha}</td><td>${d.atNormal.toFixed(4)}</td><td>${d.avg.toFixed(4)}</td><td>${((1 - d.avg) * 100).toFixed(1)}%</td></tr>`,
        )
        .join('') +
      '</tbody></table>';
    const comp = shell.state.compensation;
    if (comp !== 'none') lossTable ??= createAlbedoTableTexture();
    spheres.setCells(
      data.map((d) => ({
        label: `α = ${d.alpha}`,
        defines: FURNACE_DEFINES[comp],
        uniforms: { uAlpha: d.alpha, uDfg: dfg, uAlbedoTableGGX: lossTable },
        probe: (a) => {
          const e = albedoGGX(a.nv, d.alpha);
          const rows = [
            ['E(n·v), F = 1', e.toFixed(4)],
            ['energy lost', `${((1 - e) * 100).toFixed(1)}%`],
          ];
          if (comp === 'none') return rows;
          return [
            ...rows,
            [
              `with ${schema.compensation.options[comp]}`,
              specularAlbedoFromTable(albedoTableOnce(), a.nv, d.alpha, 1, comp).toFixed(4),
            ],
          ];
        },
      })),
    );
    describe(metalNow());
  };
  render();

  const onChanged = (changed) => {
    if (changed.includes('alphas')) {
      data = sweep(shell.state);
      ePlot.setData(eSpec());
      lossPlot.setData(lossSpec());
    }
    render();
  };
  const update = shell.connect({ title: 'White furnace', onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getAlbedos: () => data.map((d) => ({ alpha: d.alpha, atNormal: d.atNormal, average: d.avg })),
    dispose() {
      ePlot.dispose();
      lossPlot.dispose();
      spheres.dispose();
      metalView.dispose();
      dfg.dispose();
      lossTable?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'energy', schema, create: createEnergy, terms: TERMS_USED };
