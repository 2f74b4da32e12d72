// anisotropic-microsurface, the picture: a window of the surface seen from above, lit from the state's direction,
// each point shaded by the cosine between its facet's normal and the light, black where another part of the surface
// blocks the light (ray-traced); t to the right, b up, and an arrow for the light's azimuth.
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { blocked, surfaceAt } from '../../math/heightfield.js';
import { directionOf } from './model.js';

export const WINDOW_CELLS = 64; // cells of the surface across the picture
const PIXELS = 160; // ray-traced points across it (drawn smoothed to the canvas)

/** The window's picture as RGBA pixels, and the share of its points in shadow. */
export function shadedWindow(surface, thetaDeg, phiDeg) {
  const w = directionOf(thetaDeg, phiDeg);
  const rgba = new Uint8ClampedArray(PIXELS * PIXELS * 4);
  let dark = 0;
  for (let py = 0; py < PIXELS; py++) {
    for (let px = 0; px < PIXELS; px++) {
      const [x, y] = [((px + 0.5) / PIXELS) * WINDOW_CELLS, ((PIXELS - py - 0.5) / PIXELS) * WINDOW_CELLS];
      const { z, sx, sy } = surfaceAt(surface.field, x, y);
      const cos = (w[2] - sx * w[0] - sy * w[1]) / Math.hypot(sx, sy, 1);
      const shadow = cos <= 0 || blocked(surface.field, surface.maxima, [x, y, z + 1e-9], w);
      if (shadow) dark++;
      const grey = shadow ? 17 : Math.round(70 + 185 * cos);
      rgba.set([grey, grey, Math.min(255, grey + 12), 255], (py * PIXELS + px) * 4);
    }
  }
  return { rgba, shadowShare: dark / (PIXELS * PIXELS) };
}

function drawAxes(ctx, size, phiDeg) {
  ctx.strokeStyle = '#e6a700';
  ctx.fillStyle = '#e6a700';
  ctx.lineWidth = 3;
  const [cx, cy, r] = [size / 2, size / 2, size * 0.16];
  const [ex, ey] = [Math.cos((phiDeg * Math.PI) / 180), -Math.sin((phiDeg * Math.PI) / 180)];
  ctx.beginPath();
  ctx.moveTo(cx, cy);
  ctx.lineTo(cx + ex * r, cy + ey * r);
  ctx.stroke();
  ctx.beginPath(); // the arrow's head, towards the light
  ctx.arc(cx + ex * r, cy + ey * r, 5, 0, 2 * Math.PI);
  ctx.fill();
  ctx.font = 'bold 13px system-ui, sans-serif';
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(6, size - 26, 58, 20);
  ctx.fillRect(6, size - 86, 20, 58);
  ctx.fillStyle = '#111111';
  ctx.fillText('t →', 12, size - 11);
  ctx.save();
  ctx.translate(21, size - 32);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText('b →', 0, 0);
  ctx.restore();
}

/** Draws the state's window of `surface` on `canvas`; returns the share of the window in shadow. */
export function drawSurface(canvas, state, surface) {
  const { ctx, w } = sizeCanvas2d(canvas);
  const { rgba, shadowShare } = shadedWindow(surface, state.theta, state.phi);
  const image = new OffscreenCanvas(PIXELS, PIXELS);
  image.getContext('2d').putImageData(new ImageData(rgba, PIXELS, PIXELS), 0, 0);
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(image, 0, 0, w, w);
  drawAxes(ctx, w, state.phi);
  return shadowShare;
}
