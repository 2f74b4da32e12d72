// subsurface-scale's picture: a slab in cross-section, light entering at one point, the paths it takes until it
// leaves (a yellow tick where it comes back out) or is absorbed, and the shading sample around the entry.
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { randomWalk2D } from '../../math/media.js';
import { seededRandom } from '../../math/microsurface.js';
import { MAX_EVENTS, isLocal, pictureSpan } from './model.js';

const line = (ctx, x0, y0, x1, y1) => {
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
};

/** The shading sample: a pixel's footprint, seen edge-on as a circle around the entry point (dashed: too small). */
function drawSample(ctx, { cx, surfaceY, radius, local }) {
  ctx.strokeStyle = local ? '#009e73' : '#d62728';
  ctx.lineWidth = 2.5;
  ctx.setLineDash(local ? [] : [7, 5]);
  ctx.beginPath();
  ctx.arc(cx, surfaceY, radius, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.setLineDash([]);
}

/** The walks drawn, fading with the light they still carry; a tick where one comes back out. */
function drawPaths(ctx, s, { X, Y, surfaceY }) {
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
      line(ctx, X(walk.x), surfaceY - 10, X(walk.x), surfaceY);
    }
  }
}

/** The surface, the arrow of the light going in, the scale, and the verdict in words. */
function drawLabels(ctx, { w, h, surfaceY, span, radius, local }) {
  ctx.strokeStyle = '#555';
  ctx.lineWidth = 1;
  line(ctx, 0, surfaceY, w, surfaceY);
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
    Math.min(w / 2 + radius * 0.72 + 6, w - 270),
    Math.max(surfaceY + radius * 0.72 + 14, surfaceY + 30),
  );
}

/** Draws the walks of state `s` on `canvas`, with the verdict of `stats`. */
export function drawWalks(canvas, s, stats) {
  const { ctx, w, h } = sizeCanvas2d(canvas);
  const surfaceY = h * 0.32;
  const span = pictureSpan(s, stats); // mm across the canvas
  const scale = w / span;
  ctx.fillStyle = '#eef3f7';
  ctx.fillRect(0, 0, w, surfaceY);
  ctx.fillStyle = '#f6e9dc';
  ctx.fillRect(0, surfaceY, w, h - surfaceY);
  const layout = { w, h, cx: w / 2, surfaceY, span, radius: s.pixel * scale, local: isLocal(stats) };
  drawSample(ctx, layout);
  drawPaths(ctx, s, { X: (x) => w / 2 + x * scale, Y: (y) => surfaceY + y * scale, surfaceY });
  drawLabels(ctx, layout);
}
