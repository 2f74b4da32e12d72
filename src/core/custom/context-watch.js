// @ts-check
// A user-written term can hang the GPU despite the static checks (a long loop of heavy arithmetic per pixel), and
// the browser then takes the WebGL context away. This watches a renderer's context for a panel that runs user code:
// on loss it says so (and which new code was drawing, if any), on restore it hands back the last program that drew
// well, so the panel compiles it again and the widget draws what it drew before. three.js itself rebuilds its
// state on restore (WebGLRenderer listens to the same events and calls preventDefault, which permits the restore).

/**
 * @template P
 * @typedef {object} ContextWatch
 * @property {(program: P) => void} trying a program is about to draw for the first time
 * @property {() => void} drew the program being tried drew well: it is the one to bring back
 * @property {() => P | null} lastGood
 * @property {() => boolean} lost
 * @property {() => void} dispose
 */

export const LOST_MESSAGE =
  'The GPU took this view’s WebGL context away; it comes back by itself, with the last code that drew well.';
export const LOST_WHILE_TRYING =
  'The GPU took this view’s WebGL context away while your new code was drawing: it may run too long per pixel. ' +
  'The last code that drew well comes back with the context.';

/**
 * @template P a program as the panel knows it, e.g. { slotKey, code, params }
 * @param {{ domElement: HTMLCanvasElement, getContext(): WebGL2RenderingContext | WebGLRenderingContext }} renderer
 * @param {{ onLost?: (message: string, suspect: P | null) => void, onRestored?: (program: P | null) => void }} hooks
 * @returns {ContextWatch<P>}
 */
export function watchContext(renderer, { onLost, onRestored }) {
  const canvas = renderer.domElement;
  /** @type {P | null} */
  let good = null;
  /** @type {P | null} */
  let candidate = null;
  let isLost = false;
  const lostHandler = (/** @type {Event} */ event) => {
    event.preventDefault(); // without it the context never comes back
    isLost = true;
    const suspect = candidate;
    candidate = null;
    onLost?.(suspect ? LOST_WHILE_TRYING : LOST_MESSAGE, suspect);
  };
  const restoredHandler = () => {
    isLost = false;
    onRestored?.(good);
  };
  canvas.addEventListener('webglcontextlost', lostHandler);
  canvas.addEventListener('webglcontextrestored', restoredHandler);
  return {
    trying(program) {
      candidate = program;
    },
    drew() {
      if (candidate !== null) good = candidate;
      candidate = null;
    },
    lastGood: () => good,
    lost: () => isLost || renderer.getContext().isContextLost(),
    dispose() {
      canvas.removeEventListener('webglcontextlost', lostHandler);
      canvas.removeEventListener('webglcontextrestored', restoredHandler);
    },
  };
}
