// Idle pages draw nothing: every view is scrolled into sight for its first frame, progressive views run to their
// sample count, the app has nothing pending (its render loops' frames and its timed pauses, __shadingLab.pending),
// and then IDLE_FRAMES animation frames pass without a WebGL draw call (window.__drawCalls, helpers.js). Counted
// in frames and in the app's own account of its work, not in milliseconds: a loaded machine only takes longer.
import { expect } from 'vitest';
import { WAIT_MS, afterFrames } from './helpers.js';

/** Frames that must pass without a draw call once the page is idle (about a second at 60 frames a second). */
export const IDLE_FRAMES = 60;

/**
 * Resolves once the page has had nothing pending (__shadingLab.pending, debug-hooks.js) for two animation frames in
 * a row. A page without the hooks (every page of the app makes them at boot) counts as idle.
 */
export async function untilCalm(page) {
  await page.evaluate(() => (window.__calm = 0)); // each wait counts its own calm frames
  await page.waitForFunction(
    () => {
      const idle = (globalThis.__shadingLab?.pending ?? 0) === 0;
      window.__calm = idle ? (window.__calm ?? 0) + 1 : 0;
      return window.__calm >= 2;
    },
    { timeout: WAIT_MS, polling: 'raf' },
  );
}

/** Scrolls through the page a screen at a time so every view gets its first frame, then waits for idle. */
async function visitAll(page) {
  const [height, screen] = await page.evaluate(() => [document.body.scrollHeight, innerHeight]);
  for (let y = 0; y < height; y += Math.max(screen - 200, screen / 2)) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await afterFrames(page, 2); // the views now in sight asked for a frame in the first, drew it by the second
  }
  await untilCalm(page);
  // progressive views (the media path tracer, the lab's references) run until their sample count is reached,
  // then stop; they only run in sight, so each unfinished one is brought into view until it is done
  const unfinished = await page.evaluate(() =>
    Object.entries(globalThis.__shadingLab?.widgets ?? {})
      .filter(([, w]) => w.getProgress && w.getProgress().frame < w.getProgress().target)
      .map(([key]) => key),
  );
  for (const key of unfinished) {
    await page.evaluate(
      (k) => (document.querySelector(`[data-prefix="${k}"]`) ?? document.querySelector('.widget'))?.scrollIntoView(),
      key,
    );
    await page.waitForFunction(
      (k) => {
        const p = globalThis.__shadingLab.widgets[k].getProgress();
        return p.frame >= p.target;
      },
      { timeout: WAIT_MS, polling: 250 },
      key,
    );
  }
  await untilCalm(page);
}

/** Over `n` animation frames: the draw calls issued, and the frames at which the app had work pending. */
const watchFrames = (page, n) =>
  page.evaluate(
    (n) =>
      new Promise((done) => {
        const start = window.__drawCalls;
        let busy = 0;
        requestAnimationFrame(function tick() {
          if ((globalThis.__shadingLab?.pending ?? 0) > 0) busy++;
          if (--n > 0) requestAnimationFrame(tick);
          else done({ draws: window.__drawCalls - start, busy });
        });
      }),
    n,
  );

/**
 * Every view drawn and every progressive one done, the page issues no draw call over IDLE_FRAMES animation frames
 * and has no work pending at any of them.
 */
export async function expectIdle(page) {
  expect(await page.evaluate(() => typeof window.__drawCalls), 'draw calls counted (countDrawCalls)').toBe('number');
  await visitAll(page);
  expect(await watchFrames(page, IDLE_FRAMES), `over ${IDLE_FRAMES} frames once idle`).toEqual({ draws: 0, busy: 0 });
}
