// Render on demand: draw() runs at most once per animation frame, and only after invalidate().
// Nothing is drawn while the element is out of view or the tab is hidden; the pending frame is drawn
// when it comes back. A page that nothing changes issues no draw calls at all.
// ready() is false while the view cannot draw (its WebGL context is given up); the frame stays pending
// until invalidate() is called again.

import { countFrame } from '../framework/debug-hooks.js';

export function createRenderLoop(element, draw, ready = () => true) {
  let dirty = false;
  let scheduled = 0;
  let inView = true;

  const canDraw = () => inView && !document.hidden && ready();
  const frame = () => {
    scheduled = 0;
    if (!dirty || !canDraw()) return;
    dirty = false;
    countFrame();
    draw();
  };
  const schedule = () => {
    if (dirty && !scheduled && canDraw()) scheduled = requestAnimationFrame(frame);
  };

  const observer = new IntersectionObserver((entries) => {
    inView = entries[entries.length - 1].isIntersecting;
    schedule();
  });
  observer.observe(element);
  document.addEventListener('visibilitychange', schedule);

  return {
    invalidate() {
      dirty = true;
      schedule();
    },
    get inView() {
      return inView;
    },
    dispose() {
      observer.disconnect();
      document.removeEventListener('visibilitychange', schedule);
      if (scheduled) cancelAnimationFrame(scheduled);
    },
  };
}
