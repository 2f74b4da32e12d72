// The BRDF in the plane of incidence as a polar plot: angle from n on the dial, f(l, v) as the radius.
// The light handle (left) and the view handle (right) can be dragged; n, l, v, the mirror direction and
// the half vector of l and v are drawn. uPlot has no polar mode, hence a canvas of its own.

import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { DEG } from '../../math/angles.js';
import { wrapDegrees } from './azimuths.js';
import { dialGeometry, directionsOf, layOutLabels, polarLabelSpecs, SMALL_FONT, toXY } from './polar-labels.js';

const COLORS = {
  grid: '#0000001f',
  a: '#d55e00',
  b: '#009e73',
  ms: '#56b4e9',
};

/** The dial's size and centre on the canvas, in CSS pixels. */
const geometryOf = (canvas) => dialGeometry(canvas.clientWidth, canvas.clientHeight);

/** Radius rings, angle spokes every 30° and the surface line (their words: drawLabels). */
function drawGrid(ctx, g) {
  ctx.strokeStyle = COLORS.grid;
  for (const r of [0.25, 0.5, 0.75, 1]) {
    ctx.beginPath();
    ctx.arc(g.cx, g.cy, r * g.R, Math.PI, 2 * Math.PI);
    ctx.stroke();
  }
  for (let a = -90; a <= 90; a += 30) {
    ctx.beginPath();
    ctx.moveTo(g.cx, g.cy);
    ctx.lineTo(...toXY(g, a, 1));
    ctx.stroke();
  }
  ctx.strokeStyle = '#333';
  ctx.beginPath();
  ctx.moveTo(g.cx - g.R * 1.05, g.cy);
  ctx.lineTo(g.cx + g.R * 1.05, g.cy);
  ctx.stroke();
}

/** The lobes: A filled, B dashed, the multiple-scattering lobe dotted, and OpenPBR's layers' parts of A. */
function drawLobes(ctx, g, spec) {
  for (const [lobe, color, fill, dash] of [
    [spec.lobeA, COLORS.a, true, []],
    [spec.lobeB, COLORS.b, false, [6, 4]],
    [spec.lobeMS, COLORS.ms, false, [2, 3]],
  ]) {
    if (!lobe) continue;
    ctx.beginPath();
    lobe.forEach(([theta, value], i) => {
      const [x, y] = toXY(g, theta, value / spec.max);
      if (i) ctx.lineTo(x, y);
      else ctx.moveTo(x, y);
    });
    ctx.closePath();
    ctx.strokeStyle = color;
    ctx.lineWidth = 2;
    ctx.setLineDash(dash);
    ctx.stroke();
    if (fill) {
      ctx.fillStyle = `${color}33`;
      ctx.fill();
    }
  }
  for (const part of spec.parts ?? []) strokeLobe(ctx, g, part.lobe, spec.max, part.color, part.dash);
  ctx.setLineDash([]);
}

/** One layer's part of A: an open line, as the part is drawn over A's fill. */
function strokeLobe(ctx, g, lobe, max, color, dash) {
  ctx.beginPath();
  lobe.forEach(([theta, value], i) => ctx[i ? 'lineTo' : 'moveTo'](...toXY(g, theta, value / max)));
  ctx.strokeStyle = color;
  ctx.lineWidth = 2;
  ctx.setLineDash(dash);
  ctx.stroke();
}

/** The random walk's values, with bars of ± 2 standard errors along the radius. */
function drawWalkPoints(ctx, g, spec) {
  for (const [theta, value, error] of spec.points ?? []) {
    ctx.strokeStyle = ctx.fillStyle = COLORS.ms;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(...toXY(g, theta, Math.max(value - 2 * error, 0) / spec.max));
    ctx.lineTo(...toXY(g, theta, (value + 2 * error) / spec.max));
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(...toXY(g, theta, value / spec.max), 3.5, 0, 2 * Math.PI);
    ctx.fill();
  }
}

/**
 * One direction from the centre to the dial, with a dot (big for the handles l and v); `hollow`: a ring and a
 * dashed line (the view off the plane, drawn at its θv).
 */
function drawArrow(ctx, g, theta, color, name, hollow = false) {
  const [x, y] = toXY(g, theta, 1);
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = 2;
  ctx.setLineDash(name === 'mirror' || hollow ? [4, 4] : []);
  ctx.beginPath();
  ctx.moveTo(g.cx, g.cy);
  ctx.lineTo(x, y);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.beginPath();
  ctx.arc(x, y, name === 'l' || name === 'v' ? 7 : 3, 0, 2 * Math.PI);
  if (hollow) {
    ctx.fillStyle = '#ffffff';
    ctx.fill();
    ctx.stroke();
  } else ctx.fill();
}

/** Every word of the plot, each where it covers no other (polar-labels.js). */
function drawLabels(ctx, g, spec) {
  const measure = (text, font) => ((ctx.font = font), ctx.measureText(text).width);
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  for (const label of layOutLabels(polarLabelSpecs(g, spec, measure), g, spec)) {
    ctx.font = label.font;
    ctx.fillStyle = label.color;
    ctx.fillText(label.text, label.x + label.w / 2, label.y + label.h / 2);
  }
  ctx.font = SMALL_FONT;
}

/**
 * The handles: a drag moves the one nearest the pointer, the arrow keys move l (↑/↓) and v (←/→) by 5° (Shift:
 * 1°); Page Up/Page Down turn the light's azimuth φl, [ and ] the view's Δφ (the same steps, wrapped around n).
 * `shown()` is the last spec drawn (null before the first); `onDrag(partialState)`.
 */
function attachHandles(canvas, shown, onDrag) {
  let dragging = null;
  const angleAt = (e) => {
    const rect = canvas.getBoundingClientRect();
    const g = geometryOf(canvas);
    const dx = e.clientX - rect.left - g.cx;
    const dy = g.cy - (e.clientY - rect.top);
    return Math.max(-89, Math.min(89, Math.atan2(dx, Math.max(dy, 0)) / DEG));
  };
  const move = (e) => {
    if (!dragging) return;
    const a = Math.round(angleAt(e));
    onDrag(dragging === 'light' ? { lightTheta: Math.max(0, -a) } : { viewTheta: a });
  };
  const down = (e) => {
    const last = shown();
    if (!last) return;
    const a = angleAt(e);
    dragging = Math.abs(a + last.lightTheta) < Math.abs(a - last.viewTheta) ? 'light' : 'view';
    canvas.setPointerCapture(e.pointerId);
    move(e);
  };
  const key = (e) => {
    const last = shown();
    if (!last) return;
    const step = e.shiftKey ? 1 : 5;
    const moves = {
      ArrowUp: { lightTheta: last.lightTheta - step },
      ArrowDown: { lightTheta: last.lightTheta + step },
      ArrowLeft: { viewTheta: last.viewTheta - step },
      ArrowRight: { viewTheta: last.viewTheta + step },
      PageUp: { lightPhi: wrapDegrees(last.lightPhi + step) },
      PageDown: { lightPhi: wrapDegrees(last.lightPhi - step) },
      ']': { viewPhi: wrapDegrees(last.viewPhi + step, -180) },
      '[': { viewPhi: wrapDegrees(last.viewPhi - step, -180) },
    };
    moves['}'] = moves[']']; // with Shift, as a US keyboard names them
    moves['{'] = moves['['];
    if (!moves[e.key]) return;
    e.preventDefault();
    onDrag(moves[e.key]);
  };
  canvas.addEventListener('pointerdown', down);
  canvas.addEventListener('pointermove', move);
  canvas.addEventListener('pointerup', () => (dragging = null));
  canvas.addEventListener('keydown', key);
}

export function createPolarPlot(container, { onDrag }) {
  const figure = document.createElement('figure');
  figure.className = 'polar-plot';
  const caption = document.createElement('figcaption');
  caption.textContent = 'In the plane of incidence (radius: value in 1/sr, scaled to the largest)';
  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  figure.append(caption, canvas);
  container.append(figure);
  let last = null;

  /**
   * spec: { lobeA, lobeB, lobeMS, points, parts, max, lightTheta, viewTheta, lightPhi, viewPhi, halfTheta, viewOff }
   * (lobes [θ, value], θ in °; parts: [{ lobe, color, dash }], OpenPBR's layers; viewOff: v is off the plane).
   */
  function draw(spec) {
    last = spec;
    const { ctx } = sizeCanvas2d(canvas);
    const g = geometryOf(canvas);
    ctx.clearRect(0, 0, g.w, g.h);
    drawGrid(ctx, g);
    drawLobes(ctx, g, spec);
    drawWalkPoints(ctx, g, spec);
    for (const [theta, color, name] of directionsOf(spec))
      drawArrow(ctx, g, theta, color, name, name === 'v' && spec.viewOff);
    drawLabels(ctx, g, spec);
  }
  attachHandles(canvas, () => last, onDrag);
  const resize = new ResizeObserver(() => last && draw(last));
  resize.observe(canvas);

  return {
    draw,
    canvas,
    dispose() {
      resize.disconnect();
      figure.remove();
    },
  };
}
