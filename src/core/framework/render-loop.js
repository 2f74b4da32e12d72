// Render on demand: draw() runs at most once per animation frame, and only after invalidate().
// Nothing is drawn while the element is out of view or the tab is hidden; the pending frame is drawn
// when it comes back. A page that nothing changes issues no draw calls at all.
// ready() is false while the view cannot draw (its WebGL context is given up); the frame stays pending
// until invalidate() is called again.
// createSettledTask: work a change needs but no frame waits for (figures shown as words and numbers), done once
// the changes pause, so that a drag's frames come first and the last state's figures are still exact.

import { cancelFrame, cancelLater, countFrame, later, requestFrame } from './debug-hooks.js';

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
    if (dirty && !scheduled && canDraw()) scheduled = requestFrame(frame);
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
    /** Draws a pending frame at once (a resize clears the canvas: redrawn before it is painted, never blank). */
    drawNow() {
      if (scheduled) cancelFrame(scheduled);
      frame();
    },
    get inView() {
      return inView;
    },
    dispose() {
      observer.disconnect();
      document.removeEventListener('visibilitychange', schedule);
      if (scheduled) cancelFrame(scheduled);
    },
  };
}

/**
 * Runs `run` once changes have paused for `quietMs` after the last schedule(), and at least every `maxWaitMs`
 * during a long drag; flush() runs it at once when it is pending (a reader wants the figures now).
 * @param {() => void} run
 */
export function createSettledTask(run, { quietMs = 120, maxWaitMs = 500 } = {}) {
  let timer;
  let pendingSince = null; // when the oldest change not yet run came
  const fire = () => {
    cancelLater(timer);
    pendingSince = null;
    run();
  };
  return {
    schedule() {
      const now = performance.now();
      pendingSince ??= now;
      cancelLater(timer);
      timer = later(fire, Math.max(0, Math.min(quietMs, pendingSince + maxWaitMs - now)));
    },
    flush() {
      if (pendingSince !== null) fire();
    },
    cancel() {
      cancelLater(timer);
      pendingSince = null;
    },
  };
}
