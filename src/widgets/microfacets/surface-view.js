// microfacets, the magnified cut: the surface with each stretch coloured by what it sees, the facets along h,
// the bundle of light rays with their reflections and second bounces, and l, v and h as arrows in the corner.
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { DEG } from '../../math/angles.js';
import { WINDOW, dirOf, facetsSeen, halfAngleDeg, surfaceWindow, traceRays } from './model.js';

const GROUND = 0.68; // the mean surface's height on the canvas, as a share of its height from the top

const line = (ctx, [ax, ay], [bx, by]) => {
  ctx.beginPath();
  ctx.moveTo(ax, ay);
  ctx.lineTo(bx, by);
  ctx.stroke();
};

/** The surface: filled below, then each piece black where shadowed, blue and hollow where masked. */
function drawFacets(ctx, surface, win, { X, Y, P, hgt }, l, v) {
  const { profile } = surface;
  ctx.beginPath();
  ctx.moveTo(X(win.x0), hgt);
  for (let i = win.x0; i <= win.x1; i++) ctx.lineTo(X(i), Y(profile[i]));
  ctx.lineTo(X(win.x1), hgt);
  ctx.fillStyle = '#d9dce1';
  ctx.fill();
  for (const { pieces, normal } of facetsSeen(surface, win, l, v)) {
    for (const { from, to, lit, seen } of pieces) {
      ctx.strokeStyle = !lit ? '#111' : !seen ? '#0072b2' : '#9aa0a8';
      ctx.lineWidth = !lit || !seen ? 4 : 2;
      line(ctx, P(from), P(to));
      if (lit && !seen) {
        // masked stretches are hollow as well as blue: told apart from shadowed ones without colour
        ctx.strokeStyle = '#ffffff';
        ctx.lineWidth = 1.3;
        ctx.stroke();
      }
    }
    if (normal) {
      const [cx, cy] = P([normal.x, normal.y]);
      ctx.strokeStyle = '#cc79a7';
      ctx.lineWidth = 3;
      line(ctx, [cx, cy], [cx + normal.nx * 26, cy - normal.ny * 26]);
    }
  }
}

/** The rays from the light, their reflections, and (with `bounces`) the second ones; returns rays hit twice. */
function drawRays(ctx, rays, { P }, bounces) {
  for (const { start, hit, end, second, out2 } of rays) {
    ctx.strokeStyle = '#e6a70099';
    ctx.lineWidth = 1.2;
    line(ctx, P(start), P([hit.x, hit.y]));
    if (!second || bounces) {
      ctx.strokeStyle = second ? '#d62728' : '#e6a70066';
      line(ctx, P([hit.x, hit.y]), P([end.x, end.y]));
    }
    if (second && bounces) {
      ctx.setLineDash([4, 3]);
      line(ctx, P([second.x, second.y]), P([second.x + out2[0] * 3, second.y + out2[1] * 3]));
      ctx.setLineDash([]);
    }
  }
  return rays.filter((r) => r.second).length;
}

function drawArrow(ctx, d, color, label, cx) {
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = 2;
  line(ctx, [cx, 70], [cx + d[0] * 50, 70 - d[1] * 50]);
  ctx.font = 'bold 12px system-ui, sans-serif';
  ctx.fillText(label, cx + d[0] * 56 - 4, 66 - d[1] * 56);
}

/** Draws `surface` (model.js) as the state sets it up; returns how many of the rays drawn bounce twice. */
export function drawSurface(canvas, state, surface) {
  const { ctx, w, h: hgt } = sizeCanvas2d(canvas);
  ctx.fillStyle = '#f7f7f5';
  ctx.fillRect(0, 0, w, hgt);
  const win = surfaceWindow(surface.profile);
  const scale = w / WINDOW; // equal scale in x and y: angles on screen are true
  const X = (x) => (x - win.x0) * scale;
  const Y = (y) => hgt * GROUND - (y - win.mean) * scale;
  const screen = { X, Y, P: ([x, y]) => [X(x), Y(y)], hgt };
  const l = dirOf(state.lightTheta);
  const v = dirOf(state.viewTheta);
  drawFacets(ctx, surface, win, screen, l, v);
  const top = win.mean + (hgt * GROUND) / scale; // the canvas's top edge, in profile units
  const twice = drawRays(ctx, traceRays(surface, win, l, state.rays, top), screen, state.bounces);
  const hAngle = halfAngleDeg(l, v);
  drawArrow(ctx, l, '#e6a700', 'l', w - 80);
  drawArrow(ctx, v, '#0072b2', 'v', w - 80);
  drawArrow(ctx, [Math.sin(hAngle * DEG), Math.cos(hAngle * DEG)], '#cc79a7', 'h', w - 80);
  return twice;
}
