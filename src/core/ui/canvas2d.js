// Hand-drawn 2-D views (diagrams that no plotting library draws): a canvas sized to its CSS box at the
// device's pixel ratio, with a context that draws in CSS pixels.
export function sizeCanvas2d(canvas) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  canvas.width = Math.round(w * dpr);
  canvas.height = Math.round(h * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx, w, h };
}

/**
 * The axes of a square image drawn at (x0, y0) with side `size`: the same ticks on both axes ([[f, text]], f from 0
 * at the left or bottom to 1), the x axis named under them and the y axis named up its side.
 */
export function squareImageAxes(ctx, { x0, y0, size, ticks, xLabel, yLabel }) {
  ctx.fillStyle = '#333';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'center';
  for (const [f, text] of ticks) {
    ctx.fillText(text, x0 + f * size, y0 + size + 13);
    ctx.fillText(text, x0 - 16, y0 + size - f * size + 4);
  }
  ctx.fillText(xLabel, x0 + size / 2, y0 + size + 27);
  ctx.save();
  ctx.translate(10, y0 + size / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText(yLabel, 0, 0);
  ctx.restore();
}
