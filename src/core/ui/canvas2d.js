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
