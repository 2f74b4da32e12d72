// A WebGL2 canvas for a 3-D view: checks for WebGL2 (a clear message instead of a blank canvas), follows
// its container's size, draws on demand, and survives context loss. Its context is one of the page's
// budget (gl-budget.js): given up while the view is far out of sight if another view needs it, taken back
// before the view returns, and the frame redrawn from the widget's state.
//
// antialias: true (the context multisamples every frame), false (a view that smooths its own edges), or 'settled'
// (plain frames while a gesture on the widget is held, one multisampled frame once it ends: settled-antialias.js;
// stills read from the canvas get the multisampled one).
//
// onContextLost(): GPU content the widget filled once and keeps (a prefiltered environment, an
// accumulation buffer) is gone with the context; drop it so that draw() builds it again.
import * as THREE from 'three';
import { createRenderLoop } from './render-loop.js';
import { createBudgetedContext } from '../gpu/gl-context.js';
import { createSettledAntialias } from './settled-antialias.js';
import { showBlockingMessage } from './notice.js';
import { registerRedraw } from './snapshot.js';
import { describeCanvas } from './describe.js';

/** In place of the view: why there is none. Returns null, the viewport that could not be made. */
function noWebGl2(holder, canvas) {
  canvas.remove();
  showBlockingMessage(
    holder,
    'This view needs WebGL2.',
    'Your browser or device did not provide a WebGL2 context. Try a current Chrome, Firefox or Safari, or ' +
      'enable hardware acceleration. The rest of the page still works.',
  );
  return null;
}

/** The view's box in `container`, and its canvas in it. */
function createHolder(container) {
  const holder = document.createElement('div');
  holder.className = 'viewport';
  const canvas = document.createElement('canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  holder.append(canvas);
  container.append(holder);
  return { holder, canvas };
}

export function createViewport(container, { draw, onResize, onContextLost, label, antialias = true }) {
  const { holder, canvas } = createHolder(container);

  let message = null; // { kind, box }
  const say = (kind, title, text) => {
    message?.box.remove();
    message = kind ? { kind, box: showBlockingMessage(holder, title, text) } : null;
  };
  let loop = null;
  let settled = null; // with antialias: 'settled'
  const contextAntialias = antialias === true;
  const context = createBudgetedContext(
    canvas,
    { antialias: contextAntialias, alpha: false },
    {
      onLost(planned) {
        settled?.drop();
        onContextLost?.();
        if (!planned)
          say(
            'lost',
            'The graphics context was lost.',
            'It will come back by itself; if it does not, reload the page.',
          );
      },
      onRestored() {
        say(null);
        loop.invalidate();
      },
      onWaiting(waiting) {
        if (waiting)
          say(
            'paused',
            'This view is paused.',
            'More 3-D views are in sight than the browser can draw at once; it draws again when some scroll away.',
          );
        else if (message?.kind === 'paused') say(null);
      },
    },
  );
  if (!context) return noWebGl2(holder, canvas);
  if (label) describeCanvas(canvas, label); // the first words; a widget may describe the view better later
  const renderer = new THREE.WebGLRenderer({ canvas, context: context.gl, antialias: contextAntialias });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  if (antialias === 'settled') settled = createSettledAntialias(renderer, draw, () => loop.invalidate(), holder);
  const drawFrame = () => draw(renderer);
  loop = createRenderLoop(holder, settled?.frame ?? drawFrame, () => context.live);
  const drawStill = settled?.drawSettled ?? drawFrame;
  registerRedraw(canvas, () => context.live && drawStill());
  context.start();

  const resize = new ResizeObserver(() => {
    const w = Math.max(holder.clientWidth, 1);
    const h = Math.max(holder.clientHeight, 1);
    renderer.setSize(w, h, false);
    onResize?.(w, h);
    loop.invalidate();
    loop.drawNow(); // a ResizeObserver runs before paint: the cleared canvas is drawn again in the same frame
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
      settled?.dispose();
      renderer.dispose();
      context.dispose();
      holder.remove();
    },
  };
}
