// Idle pages draw nothing: every view is scrolled into sight for its first frame, progressive views run to their
// sample count, the page is back at its top with nothing pending (its render loops' frames and its timed pauses,
// __shadingLab.pending), and then IDLE_FRAMES animation frames pass without a WebGL draw call (window.__drawCalls,
// helpers.js). Counted in frames and in the app's own account of its work, not in milliseconds: a loaded machine
// only takes longer.
import { expect } from 'vitest';
import { WAIT_MS } from './helpers.js';

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

/**
 * Scrolls to `top`, then resolves once the app has had nothing pending for two animation frames in a row (the views
 * now in sight have asked for their frame and drawn it), as untilCalm does, in one DevTools call a screen.
 */
const scrollUntilCalm = (page, top) =>
  page.evaluate(
    (top) =>
      new Promise((done) => {
        window.scrollTo(0, top);
        let calm = 0;
        requestAnimationFrame(function tick() {
          calm = (globalThis.__shadingLab?.pending ?? 0) === 0 ? calm + 1 : 0;
          if (calm >= 2) done();
          else requestAnimationFrame(tick);
        });
      }),
    top,
  );

/**
 * Scrolls through the page a screen at a time, side by side (a view draws while any part of it is in sight,
 * render-loop.js), each until the app is calm, so every view has drawn its first frame; runs each progressive view
 * to its sample count; then goes back to the top and waits for calm there (the views in sight drawn again).
 */
export async function visitAll(page) {
  const [height, screen] = await page.evaluate(() => [document.body.scrollHeight, innerHeight]);
  for (let y = screen; y < height; y += screen) await scrollUntilCalm(page, y); // the top is calm (openUnderPolicy)
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
      { timeout: WAIT_MS, polling: 'raf' },
      key,
    );
  }
  await scrollUntilCalm(page, 0);
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
 * Every view drawn and every progressive one done (visitAll), the page issues no draw call over IDLE_FRAMES animation
 * frames and has no work pending at any of them. `alongside(page)`, a reader that changes nothing in the page (axe),
 * runs in those same frames (they are counted, not timed, so it cannot shorten them); resolves to what it returns.
 * @template T
 * @param {import('puppeteer-core').Page} page
 * @param {(page: import('puppeteer-core').Page) => Promise<T>} [alongside]
 * @returns {Promise<T | undefined>}
 */
export async function expectIdle(page, alongside) {
  expect(await page.evaluate(() => typeof window.__drawCalls), 'draw calls counted (countDrawCalls)').toBe('number');
  await visitAll(page);
  const [frames, result] = await Promise.all([watchFrames(page, IDLE_FRAMES), alongside?.(page)]);
  expect(frames, `over ${IDLE_FRAMES} frames once idle`).toEqual({ draws: 0, busy: 0 });
  return result;
}
