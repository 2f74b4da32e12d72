// 2-D plots on uPlot: labelled axes, shaded x-ranges (e.g. the Fresnel zones), a follow-the-size layout,
// and export of the picture (PNG, with title and legend) and of the data (CSV).
import './locale-guard.js'; // before uPlot, whose module formats numbers in navigator.language
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { canvasToPng, createToolbar, downloadCsv } from './export.js';
import { describeCanvas, spokenNumber } from '../framework/describe.js';

/** Draws vertical bands behind the series: [{ from, to, color, label }]. */
function bandsPlugin(getBands) {
  return {
    hooks: {
      drawClear: (u) => {
        const { ctx } = u;
        const { left, top, width, height } = u.bbox;
        ctx.save();
        for (const b of getBands()) {
          const x0 = Math.max(u.valToPos(b.from, 'x', true), left);
          const x1 = Math.min(u.valToPos(b.to, 'x', true), left + width);
          ctx.fillStyle = b.color;
          ctx.fillRect(x0, top, x1 - x0, height);
          if (b.label) {
            ctx.fillStyle = '#333';
            ctx.font = `${11 * uPlot.pxRatio}px system-ui, sans-serif`;
            ctx.textAlign = 'center';
            ctx.fillText(b.label, (x0 + x1) / 2, top + 14 * uPlot.pxRatio);
          }
        }
        ctx.restore();
      },
    },
  };
}

/** Draws text labels at data coordinates: [{ x, y, text, color }]. */
function annotationsPlugin(getAnnotations) {
  return {
    hooks: {
      draw: (u) => {
        const { ctx } = u;
        ctx.save();
        ctx.font = `bold ${11 * uPlot.pxRatio}px system-ui, sans-serif`;
        ctx.textBaseline = 'bottom';
        for (const a of getAnnotations()) {
          ctx.fillStyle = a.color;
          ctx.fillText(a.text, u.valToPos(a.x, 'x', true), u.valToPos(a.y, 'y', true) - 2 * uPlot.pxRatio);
        }
        ctx.restore();
      },
    },
  };
}

/** Log axes: ticks and grid lines at whole decades only (uPlot's minor decade lines crowd small plots). */
const decades = (u, axisIdx, min, max) => {
  const out = [];
  for (let e = Math.ceil(Math.log10(min)); e <= Math.floor(Math.log10(max)); e++) out.push(10 ** e);
  return out;
};

/** The plot in words: axes, and per series where it starts, ends and peaks (for the canvas's aria-label). */
export function describePlot(spec) {
  const xs = spec.data[0];
  const series = spec.series.map((s, k) => {
    const ys = spec.data[k + 1];
    const at = [];
    for (let i = 0; i < xs.length; i++) if (ys[i] != null && Number.isFinite(ys[i])) at.push(i);
    if (!at.length) return `${s.label}: no values`;
    const top = at.reduce((a, i) => (ys[i] > ys[a] ? i : a), at[0]);
    const [first, last] = [at[0], at[at.length - 1]];
    const point = (i) => `${spokenNumber(ys[i])} at ${spokenNumber(xs[i])}`;
    return `${s.label}${s.dash ? ' (dashed)' : ''}: ${point(first)}, ${point(last)}, largest ${point(top)}`;
  });
  const log = (scale) => (scale?.log ? ' (log scale)' : '');
  const across = `${spec.xLabel} from ${spokenNumber(spec.x.min)} to ${spokenNumber(spec.x.max)}${log(spec.x)}`;
  return `Plot: ${spec.title}. Across: ${across}; up: ${spec.yLabel}${log(spec.y)}. ${series.join('; ')}.`;
}

const axis = (label, extra = {}) => ({
  label,
  labelSize: 22,
  size: 48,
  stroke: '#333',
  grid: { stroke: '#0000001a' },
  ...extra,
});

/** uPlot's scales, axes and series for `spec` (see createPlot). */
function plotOptions(spec) {
  return {
    scales: {
      x: spec.x.log
        ? { time: false, distr: 3, log: 10, range: [spec.x.min, spec.x.max] }
        : { time: false, range: [spec.x.min, spec.x.max] },
      y: spec.y?.log
        ? { distr: 3, log: 10, range: [spec.y.min, spec.y.max] }
        : spec.y
          ? { range: [spec.y.min, spec.y.max] }
          : { auto: true },
    },
    // on log axes uPlot hands null for the ticks it leaves unlabelled for room
    axes: [
      axis(spec.xLabel, spec.x.log ? { splits: decades, values: spec.xValues } : { values: spec.xValues }),
      axis(
        spec.yLabel,
        spec.y?.log
          ? {
              splits: decades,
              values: (u, ticks) => ticks.map((t) => (t == null ? '' : `1e${Math.round(Math.log10(t))}`)),
              size: 56,
            }
          : {},
      ),
    ],
    series: [
      { label: spec.xLabel, value: (_, v) => (v == null ? '—' : v.toFixed(1)) },
      ...spec.series.map((s) => ({
        label: s.label,
        stroke: s.stroke,
        width: s.width ?? 2,
        dash: s.dash,
        points: { show: Boolean(s.points), size: 7, fill: s.stroke },
        spanGaps: Boolean(s.spanGaps), // a curve over x values other series own
        value: (_, v) => (v == null ? '—' : v.toFixed(4)),
      })),
    ],
  };
}

/**
 * The keyboard moves a plot's cursor as the pointer does: ←/→ one sample (Shift: ten), Home/End, Escape hides
 * it; readouts follow as on hover. getPlot(): the uPlot shown; getSpec(): its spec.
 */
function attachKeyboardCursor(holder, getPlot, getSpec) {
  let cursorIndex = null;
  holder.addEventListener('keydown', (e) => {
    const u = getPlot();
    const xs = getSpec().data[0];
    const n = xs.length;
    const step = e.shiftKey ? 10 : 1;
    const next = { ArrowLeft: (cursorIndex ?? n) - step, ArrowRight: (cursorIndex ?? -1) + step, Home: 0, End: n - 1 }[
      e.key
    ];
    if (e.key === 'Escape') {
      cursorIndex = null;
      u.setCursor({ left: -10, top: -10 });
      return;
    }
    if (next === undefined) return;
    e.preventDefault();
    cursorIndex = Math.min(Math.max(next, 0), n - 1);
    u.setCursor({ left: u.valToPos(xs[cursorIndex], 'x'), top: u.over.clientHeight / 2 });
  });
}

/**
 * spec: { title, xLabel, yLabel, x: { min, max, log }, y: { min, max, log } | null (auto),
 *         series: [{ label, stroke, dash, width, points, spanGaps }], data: [xs, ...ys], bands: [...],
 *         annotations: [...], filename, legend = true }
 * options.onCursor(index | null): the data index under the pointer, for a readout of the page's own.
 * Returns { setData(spec), dispose() }; setData rebuilds when the series change.
 */
export function createPlot(container, spec, { onCursor } = {}) {
  const wrap = document.createElement('figure');
  wrap.className = 'plot';
  const caption = document.createElement('figcaption');
  const holder = document.createElement('div');
  holder.className = 'plot-canvas';
  wrap.append(caption, holder);
  container.append(wrap);

  let current = spec;
  let u = null;
  const size = () => ({ width: Math.max(holder.clientWidth, 200), height: current.height ?? 300 });

  const build = () => {
    u?.destroy();
    caption.textContent = current.title;
    const opts = {
      ...size(),
      ...plotOptions(current),
      legend: { show: current.legend ?? true, live: true },
      cursor: { drag: { x: false, y: false } },
      hooks: { setCursor: [(p) => onCursor?.(p.cursor.idx ?? null)] },
      plugins: [bandsPlugin(() => current.bands ?? []), annotationsPlugin(() => current.annotations ?? [])],
    };
    u = new uPlot(opts, current.data, holder);
    u.ctx.canvas.tabIndex = 0; // the arrow keys move the cursor, as the pointer does
    describeCanvas(u.ctx.canvas, describePlot(current), { save: false }); // Save PNG is in its toolbar
  };
  build();

  attachKeyboardCursor(
    holder,
    () => u,
    () => current,
  );

  const resize = new ResizeObserver(() => u?.setSize(size()));
  resize.observe(holder);

  const toolbar = createToolbar(wrap, [
    {
      label: 'Save PNG',
      title: 'Save this plot as an image',
      onClick: () => canvasToPng(composite(u, current), `${current.filename}.png`),
    },
    {
      label: 'Save CSV',
      title: 'Save the plotted data',
      onClick: () =>
        downloadCsv(
          [
            { name: current.xLabel, values: current.data[0] },
            ...current.series.map((s, i) => ({ name: s.label, values: current.data[i + 1] })),
          ],
          `${current.filename}.csv`,
        ),
    },
  ]);
  toolbar.classList.add('plot-toolbar');

  return {
    setData(next) {
      const sameSeries =
        next.series.length === current.series.length &&
        next.series.every((s, i) => s.label === current.series[i].label);
      const sameScales = JSON.stringify([next.x, next.y]) === JSON.stringify([current.x, current.y]);
      current = next;
      if (sameSeries && sameScales) {
        caption.textContent = next.title;
        u.setData(next.data);
        u.redraw(false, true);
        describeCanvas(u.ctx.canvas, describePlot(next), { save: false });
      } else build();
    },
    get uplot() {
      return u;
    },
    dispose() {
      resize.disconnect();
      u?.destroy();
      wrap.remove();
    },
  };
}

/** The plot canvas with its title above and its legend below, on white, for export. */
function composite(u, spec) {
  const src = u.ctx.canvas;
  const r = uPlot.pxRatio;
  const line = 18 * r;
  const perRow = Math.max(1, Math.floor(src.width / (190 * r)));
  const legendRows = Math.ceil(spec.series.length / perRow);
  const out = document.createElement('canvas');
  out.width = src.width;
  out.height = src.height + line * (2 + legendRows);
  const ctx = out.getContext('2d');
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.fillStyle = '#111';
  ctx.font = `bold ${13 * r}px system-ui, sans-serif`;
  ctx.fillText(spec.title, 8 * r, 14 * r);
  ctx.drawImage(src, 0, line * 1.2);
  ctx.font = `${11 * r}px system-ui, sans-serif`;
  spec.series.forEach((s, i) => {
    const x = (i % perRow) * 190 * r + 8 * r;
    const y = src.height + line * (1.8 + Math.floor(i / perRow));
    ctx.strokeStyle = s.stroke;
    ctx.lineWidth = 2 * r;
    ctx.setLineDash((s.dash ?? []).map((d) => d * r));
    ctx.beginPath();
    ctx.moveTo(x, y - 4 * r);
    ctx.lineTo(x + 22 * r, y - 4 * r);
    ctx.stroke();
    ctx.fillStyle = '#111';
    ctx.fillText(s.label, x + 28 * r, y);
  });
  return out;
}
