// subsurface-scale: light entering a scattering material at one point comes back out at some distance.
// Random walks in a 2-D slab show where; a histogram gives how far; a shading-sample circle the user resizes
// shows when that distance can be ignored (the pixel is large: diffuse shading is local) and when not.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { withAlpha } from '../../core/ui/palettes.js';
import { meanFreePath, randomWalk2D, scatteringAlbedo } from '../../math/media.js';
import { seededRandom } from '../../math/microsurface.js';

export const schema = {
  sigmaS: { type: 'number', min: 0.2, max: 20, step: 0.1, default: 2, label: 'Scattering σs', unit: '1/mm' },
  sigmaA: { type: 'number', min: 0, max: 2, step: 0.01, default: 0.05, label: 'Absorption σa', unit: '1/mm' },
  pixel: { type: 'number', min: 0.05, max: 20, step: 0.05, default: 4, label: 'Shading sample radius', unit: 'mm' },
  walks: { type: 'number', min: 5, max: 200, step: 1, default: 40, label: 'Paths drawn' },
  seed: { type: 'number', min: 1, max: 999, step: 1, default: 1, label: 'Seed' },
};

const ABOUT =
  'Each path is light that entered at the marked point and was scattered until it left the surface again ' +
  '(the yellow ticks) or was absorbed on the way (paths fade with the light they still carry). When the shading ' +
  'sample (a pixel’s footprint on the surface) is much wider than these distances, the light may as well come ' +
  'out where it went in: shading stays local and a diffuse term is enough. Shrink the sample, or lower the ' +
  'scattering, and more of the light leaves outside it: then subsurface scattering has to be rendered. The walks ' +
  'are a flatland illustration: scattering is isotropic and the surface has no Fresnel boundary, so a path ' +
  'leaves the moment it crosses it; the share that comes back out is that model’s, not a material’s diffuse albedo.';

const TERMS_USED = []; // JS only (src/math/media.js): nothing here runs on the GPU
const STATS_WALKS = 20000;
const MAX_EVENTS = 2000;
const LOCAL_SHARE = 0.9; // "local" when this share of the re-emerging light exits inside the sample

function statistics(s) {
  const rand = seededRandom(s.seed * 7919);
  const exits = [];
  let back = 0;
  let stuck = 0;
  for (let i = 0; i < STATS_WALKS; i++) {
    const w = randomWalk2D({ sigmaS: s.sigmaS, rand, maxEvents: MAX_EVENTS });
    if (w.exit === 'lost') stuck++;
    else {
      const weight = Math.exp(-s.sigmaA * w.path); // light left after absorption along the path
      exits.push([Math.abs(w.x), weight]);
      back += weight;
    }
  }
  exits.sort((a, b) => a[0] - b[0]);
  const inside = exits.filter(([d]) => d <= s.pixel).reduce((t, [, w]) => t + w, 0);
  let acc = 0;
  const median = exits.find(([, w]) => (acc += w) >= back / 2)?.[0] ?? 0;
  const mean = back > 0 ? exits.reduce((t, [d, w]) => t + d * w, 0) / back : 0;
  return {
    exits,
    reflectance: back / STATS_WALKS,
    insideShare: back > 0 ? inside / back : 0,
    median,
    mean,
    stuck: stuck / STATS_WALKS,
  };
}

function histogram(stats, maxDist) {
  const bins = 60;
  const width = maxDist / bins;
  const xs = Float64Array.from({ length: bins }, (_, i) => (i + 0.5) * width);
  const ys = new Float64Array(bins);
  for (const [d, w] of stats.exits) if (d < maxDist) ys[Math.floor(d / width)] += w / STATS_WALKS / width;
  return { xs, ys };
}

export function createSubsurfaceScale(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'subsurface-scale',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const canvas = document.createElement('canvas');
  canvas.className = 'subsurface';
  const verdict = document.createElement('p');
  verdict.className = 'verdict';
  const table = document.createElement('div');
  shell.view.append(canvas, verdict);
  let stats = statistics(shell.state);
  const plotHolder = document.createElement('div');
  shell.view.append(plotHolder, table);

  const range = () => Math.max(shell.state.pixel * 1.5, stats.median * 6, 1);
  const plotSpec = () => {
    const maxDist = range();
    const { xs, ys } = histogram(stats, maxDist);
    return {
      title: 'Where the light comes back out: distance from the entry point',
      xLabel: 'Entry-to-exit distance (mm)',
      yLabel: 'light per mm',
      x: { min: 0, max: maxDist },
      y: null,
      legend: false,
      series: [{ label: 'exiting light', stroke: '#d55e00' }],
      data: [xs, ys],
      bands: [
        { from: 0, to: shell.state.pixel, color: withAlpha('#009e73', 0.15), label: 'inside the shading sample' },
      ],
      filename: 'subsurface-exit-distance',
      height: 220,
    };
  };
  const plot = createPlot(plotHolder, plotSpec());

  function draw() {
    const s = shell.state;
    const { ctx, w, h } = sizeCanvas2d(canvas);
    const surfaceY = h * 0.32;
    const span = Math.max(s.pixel * 2.6, stats.median * 8, 2); // mm across the canvas
    const scale = w / span;
    ctx.fillStyle = '#eef3f7';
    ctx.fillRect(0, 0, w, surfaceY);
    ctx.fillStyle = '#f6e9dc';
    ctx.fillRect(0, surfaceY, w, h - surfaceY);
    const X = (x) => w / 2 + x * scale;
    const Y = (y) => surfaceY + y * scale;
    // the shading sample: a pixel's footprint, seen edge-on as a circle around the entry point
    const local = stats.insideShare >= LOCAL_SHARE;
    ctx.strokeStyle = local ? '#009e73' : '#d62728';
    ctx.lineWidth = 2.5;
    ctx.setLineDash(local ? [] : [7, 5]);
    ctx.beginPath();
    ctx.arc(w / 2, surfaceY, s.pixel * scale, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.setLineDash([]);
    // the drawn paths
    const rand = seededRandom(s.seed);
    for (let i = 0; i < s.walks; i++) {
      const walk = randomWalk2D({ sigmaS: s.sigmaS, rand, maxEvents: MAX_EVENTS, keepPoints: true });
      ctx.strokeStyle = `rgba(0, 114, 178, ${0.15 + 0.6 * Math.exp(-s.sigmaA * walk.path)})`;
      ctx.lineWidth = 1;
      ctx.beginPath();
      walk.points.forEach(([x, y], k) => (k ? ctx.lineTo(X(x), Y(y)) : ctx.moveTo(X(x), Y(y))));
      ctx.stroke();
      if (walk.exit === 'back') {
        ctx.strokeStyle = '#e6a700';
        ctx.lineWidth = 3;
        ctx.beginPath();
        ctx.moveTo(X(walk.x), surfaceY - 10);
        ctx.lineTo(X(walk.x), surfaceY);
        ctx.stroke();
      }
    }
    ctx.strokeStyle = '#555';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(0, surfaceY);
    ctx.lineTo(w, surfaceY);
    ctx.stroke();
    ctx.fillStyle = '#e6a700';
    ctx.beginPath();
    ctx.moveTo(w / 2, surfaceY - 40);
    ctx.lineTo(w / 2 - 6, surfaceY - 52);
    ctx.lineTo(w / 2 + 6, surfaceY - 52);
    ctx.fill();
    ctx.fillStyle = '#333';
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillText('light in', w / 2 + 10, surfaceY - 42);
    ctx.fillText(`${span.toFixed(1)} mm across`, 8, h - 8);
    // the verdict in words too, not by the circle's colour alone (dashed when subsurface scattering is needed)
    ctx.fillStyle = local ? '#0b5d3b' : '#8c1d18';
    ctx.fillText(
      `shading sample: ${local ? 'local, diffuse is enough' : 'too small, needs subsurface scattering'}`,
      Math.min(w / 2 + s.pixel * scale * 0.72 + 6, w - 270),
      Math.max(surfaceY + s.pixel * scale * 0.72 + 14, surfaceY + 30),
    );
  }

  const render = (changed) => {
    const s = shell.state;
    if (!changed || changed.some((k) => ['sigmaS', 'sigmaA', 'seed', 'pixel'].includes(k))) {
      stats = statistics(s);
      plot.setData(plotSpec());
    }
    draw();
    const local = stats.insideShare >= LOCAL_SHARE;
    verdict.className = `verdict ${local ? 'ok' : 'warn'}`;
    verdict.textContent = local
      ? `${(stats.insideShare * 100).toFixed(1)}% of the light that comes back out leaves inside the shading sample: treat it as local, a diffuse term is enough.`
      : `Only ${(stats.insideShare * 100).toFixed(1)}% of the light that comes back out leaves inside the shading sample: the rest appears elsewhere, so subsurface scattering is needed.`;
    shell.describe(
      `${s.walks} light paths in a material with scattering ${s.sigmaS}/mm and absorption ${s.sigmaA}/mm, entering at one point; ` +
        `median entry-to-exit distance ${stats.median.toFixed(2)} mm against a shading sample of radius ${s.pixel} mm. ${verdict.textContent}`,
      canvas,
    );
    table.innerHTML =
      '<table class="data-table compact"><caption>From 20 000 paths</caption><tbody>' +
      `<tr><td>mean free path 1/σt</td><td>${meanFreePath(s.sigmaS + s.sigmaA).toFixed(3)} mm</td></tr>` +
      `<tr><td>single-scattering albedo σs/σt</td><td>${scatteringAlbedo(s.sigmaS, s.sigmaA).toFixed(3)}</td></tr>` +
      `<tr><td>light that comes back out of this 2-D slab (isotropic scattering, no refraction at the surface: not a real material’s diffuse albedo)</td><td>${(stats.reflectance * 100).toFixed(1)}%</td></tr>` +
      `<tr><td>median / mean entry-to-exit distance</td><td>${stats.median.toFixed(3)} / ${stats.mean.toFixed(3)} mm</td></tr>` +
      `<tr><td>paths still inside after ${MAX_EVENTS} events (not counted)</td><td>${(stats.stuck * 100).toFixed(2)}%</td></tr></tbody></table>`;
  };
  render(null);
  const resize = new ResizeObserver(() => draw());
  resize.observe(canvas);
  const update = shell.connect({ title: 'Subsurface scale', onChanged: render, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getStatistics: () => ({
      reflectance: stats.reflectance,
      insideShare: stats.insideShare,
      median: stats.median,
      mean: stats.mean,
    }),
    dispose() {
      resize.disconnect();
      plot.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'subsurface-scale', schema, create: createSubsurfaceScale, terms: TERMS_USED };
