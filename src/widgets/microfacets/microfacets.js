// microfacets: a 2-D microsurface under a bundle of light rays. Which facets face along h (and so reflect
// the light to the eye), which are shadowed from the light or masked from the eye, which rays bounce twice;
// and the measured share of shadowed microfacets against Smith's G1.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createPlot } from '../../core/ui/plot.js';
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import {
  castUp,
  generateProfile,
  heightBounds,
  intersectProfile,
  measuredG1,
  segmentNormal,
} from '../../math/microsurface.js';
import { smithG1Beckmann, smithG1GGX } from '../../math/visibility.js';
import { reflect } from '../../math/integrate.js';
import { DEG } from '../../math/angles.js';

export const schema = {
  kind: {
    type: 'enum',
    options: { beckmann: 'Beckmann (Gaussian slopes)', ggx: 'GGX' },
    default: 'beckmann',
    label: 'Slope distribution',
  },
  alpha: { type: 'number', min: 0.1, max: 1, step: 0.01, default: 0.5, label: 'Roughness α' },
  lightTheta: { type: 'number', min: -85, max: 85, step: 1, default: 70, label: 'Light angle θl', unit: '°' },
  viewTheta: { type: 'number', min: -85, max: 85, step: 1, default: -40, label: 'View angle θv', unit: '°' },
  rays: { type: 'number', min: 4, max: 64, step: 1, default: 28, label: 'Rays drawn' },
  bounces: { type: 'bool', default: true, label: 'Follow second bounces' },
  seed: { type: 'number', min: 1, max: 999, step: 1, default: 3, label: 'Surface seed' },
};

const ABOUT =
  'A cut through a rough surface, magnified: every facet is a tiny mirror. Yellow rays come from the light; ' +
  'a facet sends light to the eye only if its normal is the half vector h (marked in magenta). Black stretches ' +
  'are shadowed (the light cannot reach them), blue ones masked (the eye cannot see them). Some reflected rays ' +
  'hit the surface again (red): the microfacet BRDF drops that light. The plot ray-traces a profile of ' +
  '80 000 facets and compares the share of lit facets with Smith’s G1 for the same roughness.';

const PROFILE = 80000; // long enough that GGX's heavy-tailed slopes measure within ~0.03 of Smith
const WINDOW = 44; // facets shown
const H_TOLERANCE_DEG = 3;
const dirOf = (deg) => [Math.sin(deg * DEG), Math.cos(deg * DEG)];

const TERMS_USED = ['smithG1Beckmann', 'smithG1GGX'];

export function createMicrofacets(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'microfacets',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const canvas = document.createElement('canvas');
  canvas.className = 'microsurface';
  shell.view.append(canvas);
  const legend = document.createElement('p');
  legend.className = 'micro-legend';
  legend.innerHTML =
    '<span style="color:#e6a700">━</span> light rays &nbsp; <span style="color:#d62728">━</span> second bounce &nbsp; ' +
    '<span style="color:#cc79a7">▮</span> facet normal = h &nbsp; <span style="color:#111">▬</span> shadowed (solid) &nbsp; <span style="color:#0072b2">▭</span> masked (hollow)';
  shell.view.append(legend);
  const stats = document.createElement('div');
  shell.view.append(stats);

  let profile = null;
  let bounds = null;
  let g1Data = null;
  let generation = 0; // a newer profile cancels the measurement of an older one
  const smith = (c) => (shell.state.kind === 'ggx' ? smithG1GGX : smithG1Beckmann)(c, shell.state.alpha);

  const G1_OPTIONS = { perSegment: 2, margin: 0.25 };
  // Ray-tracing 18 angles takes up to ~2 s for GGX: one angle per task, so the page never stalls.
  const buildProfile = () => {
    const s = shell.state;
    profile = generateProfile(PROFILE, s.kind, s.alpha, s.seed);
    bounds = heightBounds(profile);
    const angles = Array.from({ length: 18 }, (_, i) => i * 5);
    g1Data = { angles, measured: angles.map(() => null), complete: false };
    const run = ++generation;
    const step = (i) => {
      if (run !== generation) return;
      g1Data.measured[i] = measuredG1(profile, angles[i] * DEG, G1_OPTIONS);
      plot?.setData(plotSpec());
      if (i + 1 < angles.length) setTimeout(() => step(i + 1), 0);
      else g1Data.complete = true;
    };
    setTimeout(() => step(0), 0);
  };

  const smithCurve = () => {
    const xs = Float64Array.from({ length: 90 }, (_, i) => i);
    return { xs, ys: xs.map((d) => smith(Math.cos(d * DEG))) };
  };
  const plotSpec = () => {
    const curve = smithCurve();
    const measured = Array.from(curve.xs, (d) => (d % 5 === 0 ? g1Data.measured[d / 5] : null)); // a typed array would turn null into 0
    return {
      title: 'Share of microfacets the light reaches, G1: ray-traced vs Smith',
      xLabel: 'Light angle from the mean normal (degrees)',
      yLabel: 'G1',
      x: { min: 0, max: 90 },
      y: { min: 0, max: 1.02 },
      xValues: (u, t) => t.map((v) => `${v}°`),
      series: [
        { label: 'Smith G1', stroke: '#0072b2' },
        { label: 'ray-traced profile', stroke: '#d55e00', width: 0, points: true },
      ],
      data: [curve.xs, curve.ys, measured],
      filename: 'microsurface-g1',
      height: 240,
    };
  };

  function draw() {
    const s = shell.state;
    const { ctx, w, h: hgt } = sizeCanvas2d(canvas);
    ctx.fillStyle = '#f7f7f5';
    ctx.fillRect(0, 0, w, hgt);
    const x0 = Math.floor(PROFILE / 2 - WINDOW / 2);
    const scale = w / WINDOW; // equal scale in x and y: angles on screen are true
    let mean = 0;
    for (let i = x0; i <= x0 + WINDOW; i++) mean += profile[i] / (WINDOW + 1);
    const X = (x) => (x - x0) * scale;
    const Y = (y) => hgt * 0.68 - (y - mean) * scale;
    const l = dirOf(s.lightTheta);
    const v = dirOf(s.viewTheta);
    const hv = [l[0] + v[0], l[1] + v[1]];
    const hAngle = Math.atan2(hv[0], hv[1]) / DEG;

    // the surface: fill below, then each piece coloured by what it sees
    ctx.beginPath();
    ctx.moveTo(X(x0), hgt);
    for (let i = x0; i <= x0 + WINDOW; i++) ctx.lineTo(X(i), Y(profile[i]));
    ctx.lineTo(X(x0 + WINDOW), hgt);
    ctx.fillStyle = '#d9dce1';
    ctx.fill();
    const K = 6;
    for (let i = x0; i < x0 + WINDOW; i++) {
      const rise = profile[i + 1] - profile[i];
      const [nx, ny] = segmentNormal(profile, i);
      for (let k = 0; k < K; k++) {
        const [ta, tb] = [k / K, (k + 1) / K];
        const xm = i + (ta + tb) / 2;
        const ym = profile[i] + ((ta + tb) / 2) * rise + 1e-9;
        const lit = nx * l[0] + ny * l[1] > 0 && castUp(profile, bounds, xm, ym, l[0], l[1]) === null;
        const seen = nx * v[0] + ny * v[1] > 0 && castUp(profile, bounds, xm, ym, v[0], v[1]) === null;
        ctx.strokeStyle = !lit ? '#111' : !seen ? '#0072b2' : '#9aa0a8';
        ctx.lineWidth = !lit || !seen ? 4 : 2;
        ctx.beginPath();
        ctx.moveTo(X(i + ta), Y(profile[i] + ta * rise));
        ctx.lineTo(X(i + tb), Y(profile[i] + tb * rise));
        ctx.stroke();
        if (lit && !seen) {
          // masked stretches are hollow as well as blue: told apart from shadowed ones without colour
          ctx.strokeStyle = '#ffffff';
          ctx.lineWidth = 1.3;
          ctx.stroke();
        }
      }
      const facetAngle = Math.atan2(nx, ny) / DEG;
      if (Math.abs(facetAngle - hAngle) < H_TOLERANCE_DEG) {
        const cx = X(i + 0.5);
        const cy = Y(profile[i] + rise / 2);
        ctx.strokeStyle = '#cc79a7';
        ctx.lineWidth = 3;
        ctx.beginPath();
        ctx.moveTo(cx, cy);
        ctx.lineTo(cx + nx * 26, cy - ny * 26);
        ctx.stroke();
      }
    }

    // the bundle of rays from the light, their reflections, and second bounces
    const lo = x0;
    const hi = x0 + WINDOW;
    const top = mean + (hgt * 0.68) / scale;
    let twice = 0;
    for (let r = 0; r < s.rays; r++) {
      const xs = x0 + ((r + 0.5) / s.rays) * WINDOW;
      const along = (top - profile[Math.round(xs)]) / l[1];
      const start = [xs + l[0] * along, profile[Math.round(xs)] + l[1] * along];
      const hit = intersectProfile(profile, start[0], start[1], -l[0], -l[1], lo, hi, 0);
      if (!hit) continue;
      ctx.strokeStyle = '#e6a70099';
      ctx.lineWidth = 1.2;
      ctx.beginPath();
      ctx.moveTo(X(start[0]), Y(start[1]));
      ctx.lineTo(X(hit.x), Y(hit.y));
      ctx.stroke();
      const m = segmentNormal(profile, hit.segment);
      const out = reflect([l[0], l[1], 0], [m[0], m[1], 0]);
      const second = intersectProfile(profile, hit.x, hit.y, out[0], out[1], lo - 20, hi + 20);
      const end = second ?? { x: hit.x + out[0] * 4, y: hit.y + out[1] * 4 };
      if (second) twice++;
      if (!second || s.bounces) {
        ctx.strokeStyle = second ? '#d62728' : '#e6a70066';
        ctx.beginPath();
        ctx.moveTo(X(hit.x), Y(hit.y));
        ctx.lineTo(X(end.x), Y(end.y));
        ctx.stroke();
      }
      if (second && s.bounces) {
        const m2 = segmentNormal(profile, second.segment);
        const out2 = reflect([-out[0], -out[1], 0], [m2[0], m2[1], 0]);
        ctx.setLineDash([4, 3]);
        ctx.beginPath();
        ctx.moveTo(X(second.x), Y(second.y));
        ctx.lineTo(X(second.x + out2[0] * 3), Y(second.y + out2[1] * 3));
        ctx.stroke();
        ctx.setLineDash([]);
      }
    }
    // the eye and the light, as arrows in the corner
    const arrow = (d, color, label, cx) => {
      ctx.strokeStyle = color;
      ctx.fillStyle = color;
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.moveTo(cx, 70);
      ctx.lineTo(cx + d[0] * 50, 70 - d[1] * 50);
      ctx.stroke();
      ctx.font = 'bold 12px system-ui, sans-serif';
      ctx.fillText(label, cx + d[0] * 56 - 4, 66 - d[1] * 56);
    };
    arrow(l, '#e6a700', 'l', w - 80);
    arrow(v, '#0072b2', 'v', w - 80);
    arrow([Math.sin(hAngle * DEG), Math.cos(hAngle * DEG)], '#cc79a7', 'h', w - 80);
    return twice;
  }

  let plot = null;
  const render = (rebuild) => {
    if (rebuild) buildProfile();
    const twice = draw();
    const s = shell.state;
    const c = Math.cos(Math.abs(s.lightTheta) * DEG);
    const measured = measuredG1(profile, Math.abs(s.lightTheta) * DEG, G1_OPTIONS);
    stats.innerHTML =
      `<table class="data-table compact"><caption>At the light angle ${Math.abs(s.lightTheta)}°</caption><tbody>` +
      `<tr><td>shadowed share of facets facing the light, ray-traced</td><td>${((1 - measured) * 100).toFixed(2)}%</td></tr>` +
      `<tr><td>the same, predicted by Smith (1 − G1)</td><td>${((1 - smith(c)) * 100).toFixed(2)}%</td></tr>` +
      `<tr><td>rays drawn that bounce twice</td><td>${twice} of ${s.rays}</td></tr></tbody></table>`;
    const hDeg =
      Math.atan2(
        Math.sin(s.lightTheta * DEG) + Math.sin(s.viewTheta * DEG),
        Math.cos(s.lightTheta * DEG) + Math.cos(s.viewTheta * DEG),
      ) / DEG;
    shell.describe(
      `Magnified cross-section of a rough surface, ${schema.kind.options[s.kind]}, α ${s.alpha}: ${s.rays} rays from the light at ${s.lightTheta}°, ` +
        `eye at ${s.viewTheta}°, so the half vector h is ${hDeg.toFixed(1)}° from the mean normal; facets along h are marked. ` +
        `Shadowed share of the facets facing the light: ${((1 - measured) * 100).toFixed(1)}% ray-traced, ${((1 - smith(c)) * 100).toFixed(1)}% by Smith. ` +
        `${twice} of ${s.rays} rays hit the surface a second time${s.bounces ? ' (drawn in red)' : ''}.`,
      canvas,
    );
    if (rebuild) {
      if (plot) plot.setData(plotSpec());
      else plot = createPlot(shell.view, plotSpec());
    }
  };
  render(true);
  const resize = new ResizeObserver(() => draw());
  resize.observe(canvas);

  const onChanged = (changed) => render(changed.some((k) => ['kind', 'alpha', 'seed'].includes(k)));
  const update = shell.connect({ title: 'Microsurface', onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    /** Ray-traced G1 at 0°, 5°, … 85° and Smith's, for tests. */
    getG1: () => ({
      complete: g1Data.complete,
      angles: [...g1Data.angles],
      measured: [...g1Data.measured],
      smith: g1Data.angles.map((d) => smith(Math.cos(d * DEG))),
    }),
    dispose() {
      generation++;
      resize.disconnect();
      plot?.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'microfacets', schema, create: createMicrofacets, terms: TERMS_USED };
