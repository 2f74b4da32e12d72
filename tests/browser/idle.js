// Idle pages draw nothing: every view is scrolled into sight for its first frame, progressive views run to their
// sample count, and then two seconds pass without a WebGL draw call (window.__drawCalls, helpers.js).
import { expect } from 'vitest';
import { settle } from './helpers.js';

/** Scrolls through the page so every view gets its first frame, then lets it settle. */
async function visitAll(page) {
  const height = await page.evaluate(() => document.body.scrollHeight);
  for (let y = 0; y < height; y += 500) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await settle(page, 300);
  }
  await settle(page, 1500);
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
}

/** Every view drawn and every progressive one done, the page issues no draw call over two seconds. */
export async function expectIdle(page) {
  await visitAll(page);
  const before = await page.evaluate(() => window.__drawCalls);
  await new Promise((r) => setTimeout(r, 2000));
  expect(await page.evaluate(() => window.__drawCalls), 'draw calls while idle').toBe(before);
}
