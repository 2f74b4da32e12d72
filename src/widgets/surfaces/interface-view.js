// A flat interface in cross-section: one ray in, the reflected share up (exact Fresnel), the refracted share
// down (Snell), and what the material does with it: a metal absorbs it within nanometres, a non-metal
// scatters it, and some comes back out.
import { randomWalk2D } from '../../math/media.js';
import { seededRandom } from '../../math/microsurface.js';
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { DEG } from '../../math/angles.js';

/** spec: model.js's interfaceSpec: { theta (deg), F, etaRefr (real index for Snell), metal, depthNm, name } */
export function drawInterface(canvas, spec) {
  const { ctx, w, h } = sizeCanvas2d(canvas);
  const y0 = h * 0.45;
  const cx = w / 2;
  const L = Math.min(w * 0.42, y0 * 0.95);
  ctx.fillStyle = '#eef3f7';
  ctx.fillRect(0, 0, w, y0);
  ctx.fillStyle = spec.metal ? '#d9d2c3' : '#f3e6d6';
  ctx.fillRect(0, y0, w, h - y0);
  ctx.strokeStyle = '#555';
  ctx.beginPath();
  ctx.moveTo(0, y0);
  ctx.lineTo(w, y0);
  ctx.stroke();
  ctx.setLineDash([4, 4]);
  ctx.beginPath();
  ctx.moveTo(cx, y0 - L);
  ctx.lineTo(cx, y0 + L * 0.6);
  ctx.stroke();
  ctx.setLineDash([]);
  const t = spec.theta * DEG;
  const ray = (x1, y1, x2, y2, width, color) => {
    ctx.strokeStyle = color;
    ctx.lineWidth = Math.max(width, 0.6);
    ctx.beginPath();
    ctx.moveTo(x1, y1);
    ctx.lineTo(x2, y2);
    ctx.stroke();
  };
  const W = 14; // line width of the incoming light
  ray(cx - L * Math.sin(t), y0 - L * Math.cos(t), cx, y0, W, '#e6a700');
  ray(cx, y0, cx + L * Math.sin(t), y0 - L * Math.cos(t), W * spec.F, '#e6a700');
  ctx.fillStyle = '#222';
  ctx.font = '13px system-ui, sans-serif';
  ctx.fillText(`in, θ = ${spec.theta.toFixed(0)}°`, cx - L * Math.sin(t) - 10, y0 - L * Math.cos(t) - 8);
  ctx.fillText(`reflected ${(spec.F * 100).toFixed(1)}%`, cx + L * Math.sin(t) * 0.6 + 10, y0 - L * Math.cos(t) * 0.6);
  const sinT = Math.sin(t) / spec.etaRefr;
  const tt = Math.asin(Math.min(sinT, 1));
  const depth = L * 0.55;
  if (spec.metal) {
    // in a metal the refracted light dies within a few tens of nanometres: drawn as a short stub
    ray(cx, y0, cx + 12 * Math.sin(tt), y0 + 12 * Math.cos(tt), W * (1 - spec.F), '#b5651d');
    ctx.fillText(
      `refracted ${((1 - spec.F) * 100).toFixed(1)}%: absorbed within ~${spec.depthNm.toFixed(0)} nm (λ/4πk)`,
      cx + 16,
      y0 + 34,
    );
  } else {
    ray(cx, y0, cx + 40 * Math.sin(tt), y0 + 40 * Math.cos(tt), W * (1 - spec.F), '#e6a700aa');
    // inside a non-metal the light scatters: walks that start along the refracted ray (Snell's angle);
    // the ones that reach the surface again are the diffuse light
    const rand = seededRandom(7);
    const scale = depth / 4;
    for (let i = 0; i < 14; i++) {
      const walk = randomWalk2D({ sigmaS: 2, entryAngle: tt, rand, keepPoints: true, maxEvents: 80 });
      ctx.strokeStyle = walk.exit === 'back' ? '#0072b2aa' : '#0072b244';
      ctx.lineWidth = 1;
      ctx.beginPath();
      walk.points.forEach(([x, y], k) =>
        k ? ctx.lineTo(cx + x * scale, y0 + y * scale) : ctx.moveTo(cx + x * scale, y0 + y * scale),
      );
      ctx.stroke();
      if (walk.exit === 'back') ray(cx + walk.x * scale, y0, cx + walk.x * scale, y0 - 14, 2, '#0072b2');
    }
    ctx.fillStyle = '#222';
    const refracted = `refracted ${((1 - spec.F) * 100).toFixed(1)}%`;
    ctx.fillText(
      `${refracted}: scattered inside; where paths reach the surface again, light leaves (diffuse)`,
      12,
      h - 12,
    );
  }
}
