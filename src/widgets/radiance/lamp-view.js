// radiance, the eye's view of the lamp: a grid of pixels and the lamp as a disk of the same brightness at any
// distance, only smaller.
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';

const FIELD_DEG = 60; // the drawn eye's field of view: the lamp spans it at 0.1 m and about a pixel at 30 m

/** Draws the lamp of model.js's lampView `view` at the state's distance. */
export function drawLamp(canvas, state, view) {
  const { ctx, w, h } = sizeCanvas2d(canvas);
  ctx.fillStyle = '#1b1e24';
  ctx.fillRect(0, 0, w, h);
  const pixel = 8; // one drawn "pixel" of an eye whose field is FIELD_DEG across
  const scale = w / FIELD_DEG;
  ctx.strokeStyle = '#ffffff14';
  for (let x = 0; x < w; x += pixel) ctx.strokeRect(x, 0, pixel, h);
  for (let y = 0; y < h; y += pixel) ctx.strokeRect(0, y, w, pixel);
  const r = Math.max(view.angularRadiusDeg * scale, 0.5);
  ctx.fillStyle = '#ffe9b0'; // the same value at every distance: radiance does not fall off
  ctx.beginPath();
  ctx.arc(w / 2, h / 2, r, 0, 2 * Math.PI);
  ctx.fill();
  ctx.fillStyle = '#e8e8e8';
  ctx.font = '12px system-ui, sans-serif';
  const span = `${(2 * view.angularRadiusDeg).toFixed(2)}°`;
  ctx.fillText(`the eye's view, ${FIELD_DEG}° across: the lamp at ${state.distance} m spans ${span}`, 8, h - 10);
}
