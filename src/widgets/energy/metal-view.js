// The energy widget's coloured-metal view: a metal's albedo per channel against the view angle with single
// scattering, Kulla–Conty and Turquin (from the albedo table, as the spheres compute them) and random-walk
// points, and the colours they give head-on: the bounces that come back make gold more saturated, since a
// channel that reflects more also gets more of its lost light back.
import { createPlot } from '../../core/ui/plot.js';
import { rgbToHex } from '../../core/ui/palettes.js';
import { albedoTableOnce } from '../../core/gpu/albedo-table-texture.js';
import { linearToSrgb } from '../../math/color.js';
import { materialByKey } from '../../math/materials.js';
import { termEntry } from '../../math/catalogue/index.js';
import { whileLoading } from '../../core/framework/debug-hooks.js';
import { COMPENSATIONS, WALK_DEGREES, WALK_PATHS, albedoCurves, saturation } from './compensation.js';

const CHANNELS = [
  ['R', '#c0392b'],
  ['G', '#27ae60'],
  ['B', '#2c6fbb'],
];
/** Each compensation's line pattern (solid where none is given). */
const DASHES = { none: [2, 4], turquin: [9, 4] };
const DEGREES = [...new Set([...Array.from({ length: 45 }, (_, i) => 2 * i), ...WALK_DEGREES])].sort((a, b) => a - b);

/**
 * The walk per (metal, alpha), run in a module worker and cached; `get` gives the points or null and asks for
 * them once, `onResult(key)` says when they arrived. Each job is counted in the page's pending work until its
 * result comes back (or the view closes), so a test waiting for idle waits for the walk too.
 */
function createWalkCache(onResult) {
  const done = new Map();
  const asked = new Map(); // key → resolves the job's count in the pending work
  let worker = null;
  return {
    get(metal, alpha) {
      const key = `${metal.key}|${alpha}`;
      if (done.has(key) || asked.has(key)) return done.get(key) ?? null;
      whileLoading(new Promise((resolve) => asked.set(key, resolve)));
      worker ??= new Worker(new URL('./walk-worker.js', import.meta.url), { type: 'module' });
      worker.onmessage = ({ data }) => {
        done.set(data.id, data.walk);
        asked.get(data.id)?.();
        onResult(data.id);
      };
      worker.postMessage({ id: key, alpha, f0: metal.linear });
      return null;
    },
    dispose: () => {
      worker?.terminate();
      for (const resolve of asked.values()) resolve();
    },
  };
}

function plotSpec({ metal, alpha, curves, walk }) {
  const series = [];
  const data = [DEGREES];
  for (const key of COMPENSATIONS) {
    CHANNELS.forEach(([ch, stroke], c) => {
      series.push({ label: `${ch}, ${termEntry('compensation', key).short}`, stroke, dash: DASHES[key] });
      data.push(curves[key].map((rgb) => rgb[c]));
    });
  }
  CHANNELS.forEach(([ch, stroke], c) => {
    series.push({ label: `${ch}, random walk`, stroke, width: 0, points: true });
    data.push(DEGREES.map((deg) => walk?.find((p) => p.deg === deg)?.albedo[c] ?? null));
  });
  return {
    title: `${metal.name} (linear F0 ${metal.linear.join(', ')}) at α = ${alpha}: albedo per channel, all bounces`,
    xLabel: 'View angle θv (degrees)',
    yLabel: 'albedo',
    x: { min: 0, max: 90 },
    y: { min: 0, max: 1.02 },
    xValues: (u, t) => t.map((v) => `${v}°`),
    series,
    data,
    filename: `metal-albedo-${metal.key}`,
    height: 280,
  };
}

/** The models' head-on colours, [name, linear rgb | undefined while the walk runs], the walk last. */
function headOnColours({ curves, walk }) {
  const walkRow = [`random walk (${WALK_PATHS / 1000}k paths${walk ? '' : ', running'})`, walk?.[0].albedo];
  return [...COMPENSATIONS.map((key) => [termEntry('compensation', key).short, curves[key][0]]), walkRow];
}
const hexOf = (rgb) => rgbToHex(rgb.map(linearToSrgb));

/** The same colours large enough to compare by eye, each named. */
function patches(shown) {
  const patch = ([name, rgb]) =>
    `<figure><span class="patch" style="background:${rgb ? hexOf(rgb) : 'transparent'}"></span>` +
    `<figcaption>${name}</figcaption></figure>`;
  const { metal, alpha } = shown;
  const head = `<p class="patches-head">${metal.name} at α = ${alpha}, seen head-on, as each model colours it:</p>`;
  return `${head}<div class="metal-patches">${headOnColours(shown).map(patch).join('')}</div>`;
}

function swatchTable(shown) {
  const { metal, alpha } = shown;
  const rows = headOnColours(shown);
  const swatch = (rgb) => `<span class="swatch" style="background:${hexOf(rgb)}"></span>`;
  const row = ([name, rgb]) =>
    rgb
      ? `<tr><td>${name}</td><td>${swatch(rgb)}</td><td>${rgb.map((x) => x.toFixed(3)).join(', ')}</td>` +
        `<td>${saturation(rgb).toFixed(3)}</td></tr>`
      : `<tr class="walk-pending"><td>${name}</td><td></td><td>…</td><td>…</td></tr>`;
  return (
    `<table class="data-table compact"><caption>${metal.name} at α = ${alpha}, seen head-on: the colour each ` +
    'model gives (linear albedo, shown in sRGB)</caption><thead><tr><th>model</th><th>colour</th>' +
    '<th>albedo R, G, B</th><th>saturation (1 − min/max)</th></tr></thead><tbody>' +
    rows.map(row).join('') +
    '</tbody></table>'
  );
}

/**
 * The plot and swatches. Curves are drawn at once; the walk's points when the worker sends them (the newest
 * (metal, alpha) only: a result for an older choice is cached, never drawn over a newer one). `onWalk()` is
 * called when the shown choice gets its points.
 */
export function createMetalView(container, onWalk = () => {}) {
  const holder = document.createElement('div');
  const swatches = document.createElement('div');
  container.append(holder, swatches);
  let plot = null;
  let last = null;
  const draw = () => {
    if (plot) plot.setData(plotSpec(last));
    else plot = createPlot(holder, plotSpec(last));
    swatches.innerHTML = patches(last) + swatchTable(last);
  };
  const walks = createWalkCache((key) => {
    if (!last || key !== `${last.metal.key}|${last.alpha}`) return;
    last = { ...last, walk: walks.get(last.metal, last.alpha) };
    draw();
    onWalk();
  });
  return {
    /** The shown { metal, alpha, curves, walk } (walk null until it arrives), redrawn when the choice changed. */
    update(metalKey, alpha) {
      if (last && last.metal.key === metalKey && last.alpha === alpha) return last;
      const metal = materialByKey(metalKey);
      const curves = albedoCurves(albedoTableOnce(), alpha, metal.linear, DEGREES);
      last = { metal, alpha, curves, walk: walks.get(metal, alpha) };
      draw();
      return last;
    },
    dispose() {
      walks.dispose();
      plot?.dispose();
      holder.remove();
      swatches.remove();
    },
  };
}
