// @ts-check
// A still picture of what a widget shows: its canvases (WebGL views and plots) composited where they sit on the
// page, for the embed protocol's `snapshot`, the slides' print mode and printed chapter pages. A WebGL view
// keeps no frame after it is shown (no preserveDrawingBuffer), so each registers a redraw that is run right
// before its canvas is copied, in the same task, while its drawing buffer holds the frame.

/** @type {WeakMap<HTMLCanvasElement, () => unknown>} */
const redraws = new WeakMap();

/**
 * `redraw()` draws the canvas's frame now (the viewport's draw), or returns false when it cannot.
 * @param {HTMLCanvasElement} canvas
 * @param {() => unknown} redraw
 */
export function registerRedraw(canvas, redraw) {
  redraws.set(canvas, redraw);
}

/**
 * A new 2-D canvas of `width` × `height` pixels, filled with the page's background.
 * @param {number} width
 * @param {number} height
 */
function backdrop(width, height) {
  const out = document.createElement('canvas');
  out.width = width;
  out.height = height;
  const ctx = /** @type {CanvasRenderingContext2D} */ (out.getContext('2d'));
  ctx.fillStyle = getComputedStyle(document.body).backgroundColor || '#fff';
  ctx.fillRect(0, 0, width, height);
  return { out, ctx };
}

/**
 * One canvas as a 2-D canvas of its own pixel size, on the page's background, its frame redrawn first.
 * @param {HTMLCanvasElement} canvas
 */
export function stillOf(canvas) {
  const { out, ctx } = backdrop(canvas.width, canvas.height);
  redraws.get(canvas)?.();
  ctx.drawImage(canvas, 0, 0);
  return out;
}

/**
 * The canvases under `root` composited into one 2-D canvas of their bounding box (CSS pixels × scale), or null.
 * @param {ParentNode} root
 */
export function compositeCanvases(root, scale = Math.min(globalThis.devicePixelRatio || 1, 2)) {
  const canvases = [...root.querySelectorAll('canvas')].filter((c) => c.width && c.height && c.getClientRects().length);
  if (!canvases.length) return null;
  const rects = canvases.map((c) => c.getBoundingClientRect());
  const left = Math.min(...rects.map((r) => r.left));
  const top = Math.min(...rects.map((r) => r.top));
  const { out, ctx } = backdrop(
    Math.round((Math.max(...rects.map((r) => r.right)) - left) * scale),
    Math.round((Math.max(...rects.map((r) => r.bottom)) - top) * scale),
  );
  canvases.forEach((canvas, i) => {
    redraws.get(canvas)?.();
    const r = rects[i];
    ctx.drawImage(canvas, (r.left - left) * scale, (r.top - top) * scale, r.width * scale, r.height * scale);
  });
  return out;
}

/**
 * The view of a widget (its `.widget-view`, without the controls) as a PNG data URL, or null.
 * @param {Element | null | undefined} widgetRoot
 */
export function snapshotWidget(widgetRoot) {
  const view = widgetRoot?.querySelector('.widget-view') ?? widgetRoot;
  return view ? (compositeCanvases(view)?.toDataURL('image/png') ?? null) : null;
}
