// anisotropic-microsurface, the picture: a window of the surface seen from above, lit from the state's direction,
// each point shaded by the cosine between its facet's normal and the light, dark blue where another part of the
// surface blocks the light (ray-traced), black where the facet faces away; t to the right, b up, and an arrow
// pointing to the light's azimuth.
import { sizeCanvas2d } from '../../core/ui/canvas2d.js';
import { blocked, surfaceAt } from '../../math/heightfield.js';
import { directionOf } from './model.js';

export const WINDOW_CELLS = 48; // cells of the surface across the picture
// ray-traced points across it (drawn smoothed to the canvas): a quarter of them while a control moves, then all
export const PIXELS = { coarse: 96, fine: 192 };

/** The window's picture, `size` points square, as RGBA pixels, and the share of its points in shadow. */
export function shadedWindow(surface, thetaDeg, phiDeg, size = PIXELS.fine) {
  const w = directionOf(thetaDeg, phiDeg);
  const rgba = new Uint8ClampedArray(size * size * 4);
  let dark = 0;
  for (let py = 0; py < size; py++) {
    for (let px = 0; px < size; px++) {
      // in the field's cells (a surface of every other point has cells twice the size: model.js)
      const cells = WINDOW_CELLS / surface.every;
      const [x, y] = [((px + 0.5) / size) * cells, ((size - py - 0.5) / size) * cells];
      const { z, sx, sy } = surfaceAt(surface.field, x, y);
      const cos = (w[2] - sx * w[0] - sy * w[1]) / Math.hypot(sx, sy, 1);
      const shadow = cos <= 0 || blocked(surface.field, surface.maxima, [x, y, z + 1e-9], w);
      if (shadow) dark++;
      // in shadow the facet's own cosine still shows a little, so the bumps keep their form
      const lit = 70 + 185 * cos;
      const rgb = cos <= 0 ? [12, 12, 16] : shadow ? [20 + 50 * cos, 30 + 60 * cos, 70 + 90 * cos] : [lit, lit, lit];
      rgba.set([...rgb, 255], (py * size + px) * 4);
    }
  }
  return { rgba, shadowShare: dark / (size * size) };
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
  ctx.fillStyle = '#111111';
  const label = 'to the light';
  const [lx, ly] = [cx + ex * (r + 12) - (ex < 0 ? ctx.measureText(label).width : 0), cy + ey * (r + 12) + 4];
  ctx.fillRect(lx - 3, ly - 14, ctx.measureText(label).width + 6, 19);
  ctx.fillStyle = '#ffd27a';
  ctx.fillText(label, lx, ly);
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

/**
 * Draws the state's window of `surface` on `canvas` at `detail` ('coarse' or 'fine', PIXELS); returns the share of
 * the window in shadow.
 */
export function drawSurface(canvas, state, surface, detail = 'fine') {
  const { ctx, w } = sizeCanvas2d(canvas);
  const size = PIXELS[detail];
  const { rgba, shadowShare } = shadedWindow(surface, state.theta, state.phi, size);
  const image = new OffscreenCanvas(size, size);
  image.getContext('2d').putImageData(new ImageData(rgba, size, size), 0, 0);
  ctx.imageSmoothingEnabled = true;
  ctx.drawImage(image, 0, 0, w, w);
  drawAxes(ctx, w, state.phi);
  return shadowShare;
}
