// A WebGL2 canvas for a 3-D view: checks for WebGL2 (a clear message instead of a blank canvas), follows
// its container's size, draws on demand, and survives context loss.
import * as THREE from 'three';
import { createRenderLoop } from './render-loop.js';
import { showBlockingMessage } from './notice.js';

export function createViewport(container, { draw, onResize, label }) {
  const holder = document.createElement('div');
  holder.className = 'viewport';
  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  if (label) canvas.setAttribute('aria-label', label);
  holder.append(canvas);
  container.append(holder);

  const gl = canvas.getContext('webgl2', { antialias: true, alpha: false });
  if (!gl) {
    canvas.remove();
    showBlockingMessage(holder, 'This view needs WebGL2.', 'Your browser or device did not provide a WebGL2 context. Try a current Chrome, Firefox or Safari, or enable hardware acceleration. The rest of the page still works.');
    return null;
  }
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  const loop = createRenderLoop(holder, () => draw(renderer));

  let lostMessage = null;
  const onLost = (e) => {
    e.preventDefault();
    lostMessage ??= showBlockingMessage(holder, 'The graphics context was lost.', 'It will come back by itself; if it does not, reload the page.');
  };
  const onRestored = () => {
    lostMessage?.remove();
    lostMessage = null;
    loop.invalidate();
  };
  canvas.addEventListener('webglcontextlost', onLost);
  canvas.addEventListener('webglcontextrestored', onRestored);

  const resize = new ResizeObserver(() => {
    const w = Math.max(holder.clientWidth, 1);
    const h = Math.max(holder.clientHeight, 1);
    renderer.setSize(w, h, false);
    onResize?.(w, h);
    loop.invalidate();
  });
  resize.observe(holder);

  return {
    renderer,
    canvas,
    holder,
    invalidate: loop.invalidate,
    get inView() {
      return loop.inView;
    },
    dispose() {
      resize.disconnect();
      loop.dispose();
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
      renderer.dispose();
      holder.remove();
    },
  };
}
