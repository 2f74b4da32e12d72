// Skip what a scene does not need, measured: WebGL draw calls are counted in the page itself.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open, settle, widget } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const PAGES = ['index.html', 'brdf.html', 'microfacets.html', 'fresnel.html', 'ndf.html', 'visibility.html', 'performance.html', 'parity.html'];
const draws = (page) => page.evaluate(() => window.__drawCalls);

/** Scroll through the page so every view gets its first frame, then let it settle. */
async function visitAll(page) {
  const height = await page.evaluate(() => document.body.scrollHeight);
  for (let y = 0; y < height; y += 500) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await settle(page, 300);
  }
  await settle(page, 1500);
}

describe('idle pages draw nothing', () => {
  for (const path of PAGES) {
    it(path, async () => {
      const page = await open(browser, path);
      await visitAll(page);
      const before = await draws(page);
      await new Promise((r) => setTimeout(r, 2000));
      expect(await draws(page)).toBe(before);
      expect(page.errors).toEqual([]);
      await page.close();
    });
  }
});

describe('views out of sight draw nothing', () => {
  it('a widget scrolled out of view does not draw on a state change, and draws once back in view', async () => {
    const page = await open(browser, 'fresnel.html');
    await widget(page, 'zones');
    await page.$eval('[data-slot="fresnel-zones"]', (el) => el.scrollIntoView());
    await settle(page, 800);
    await page.evaluate(() => window.scrollTo(0, 0)); // the zones view is far below
    await settle(page, 500);
    const before = await draws(page);
    await page.evaluate(() => globalThis.__shadingLab.widgets.zones.update({ mode: 'zones-lh' }));
    await settle(page, 800);
    expect(await draws(page)).toBe(before);
    await page.$eval('[data-slot="fresnel-zones"]', (el) => el.scrollIntoView());
    await settle(page, 800);
    expect(await draws(page)).toBeGreaterThan(before);
    await page.close();
  });

  it('a hidden tab does not draw, and draws the pending frame when shown again', async () => {
    const page = await open(browser, 'embed.html?w=fresnel-zones');
    await widget(page, 'fresnel-zones');
    const setHidden = (hidden) =>
      page.evaluate((h) => {
        Object.defineProperty(document, 'hidden', { configurable: true, get: () => h });
        document.dispatchEvent(new Event('visibilitychange'));
      }, hidden);
    await setHidden(true);
    const before = await draws(page);
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ lightTheta: 20 }));
    await settle(page, 600);
    expect(await draws(page)).toBe(before);
    await setHidden(false);
    await settle(page, 600);
    expect(await draws(page)).toBeGreaterThan(before);
    await page.close();
  });
});
