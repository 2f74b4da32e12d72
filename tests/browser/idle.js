// Idle pages draw nothing: every view is scrolled into sight for its first frame, progressive views run to their
// sample count, and then two seconds pass without a WebGL draw call (window.__drawCalls, helpers.js).
import { expect } from 'vitest';
import { settle, untilSteady } from './helpers.js';

/**
 * Resolves once the page has issued no draw call for 500 ms (a view still drawing its first frames, or a settled
 * frame after them, counts as busy), or after 30 s: a page that never goes quiet is then caught by expectIdle's own
 * check, with its message.
 */
const untilQuiet = (page) => untilSteady(page, 'drawCalls').catch(() => {});

/** Scrolls through the page a screen at a time so every view gets its first frame, then lets it settle. */
async function visitAll(page) {
  const [height, screen] = await page.evaluate(() => [document.body.scrollHeight, innerHeight]);
  for (let y = 0; y < height; y += Math.max(screen - 200, screen / 2)) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await settle(page, 200);
  }
  await untilQuiet(page);
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
      { timeout: 120_000, polling: 250 },
      key,
    );
  }
  await untilQuiet(page);
}

/** Every view drawn and every progressive one done, the page issues no draw call over two seconds. */
export async function expectIdle(page) {
  expect(await page.evaluate(() => typeof window.__drawCalls), 'draw calls counted (countDrawCalls)').toBe('number');
  await visitAll(page);
  const before = await page.evaluate(() => window.__drawCalls);
  await new Promise((r) => setTimeout(r, 2000));
  expect(await page.evaluate(() => window.__drawCalls), 'draw calls while idle').toBe(before);
}
