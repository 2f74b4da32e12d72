// Skip what a scene does not need, measured: WebGL draw calls are counted in the page itself. That an idle page draws
// nothing is checked where every page is loaded under the policy (axe.test.js).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, afterFrames, launchBrowser, open, untilIdle, untilSteady, widget } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const draws = (page) => page.evaluate(() => window.__drawCalls);
/** Waits until the page has drawn more than `n` calls (a frame it owes). */
const untilDrawsAfter = (page, n) => page.waitForFunction((k) => window.__drawCalls > k, { timeout: WAIT_MS }, n);

describe('views out of sight draw nothing', () => {
  it('a widget scrolled out of view does not draw on a state change, and draws once back in view', async () => {
    const page = await open(browser, 'fresnel.html');
    await widget(page, 'zones');
    await page.$eval('[data-slot="fresnel-zones"]', (el) => el.scrollIntoView());
    await untilSteady(page, 'drawCalls'); // its frames and its zone shares' read-back done
    await page.evaluate(() => window.scrollTo(0, 0)); // the zones view is far below
    await untilSteady(page, 'drawCalls');
    const before = await draws(page);
    await page.evaluate(() => globalThis.__shadingLab.widgets.zones.update({ mode: 'zones-lh' }));
    // (a window for what must not come, counted in frames once the app has nothing asked for: it can let a wrong
    // draw through, never fail a right one)
    await untilIdle(page);
    await afterFrames(page, 30);
    expect(await draws(page)).toBe(before);
    await page.$eval('[data-slot="fresnel-zones"]', (el) => el.scrollIntoView());
    await untilDrawsAfter(page, before);
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
    await untilSteady(page, 'drawCalls'); // its first frames and its zone shares' read-back done
    await setHidden(true);
    const before = await draws(page);
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ lightTheta: 20 }));
    await untilIdle(page); // (a window for what must not come, as above)
    await afterFrames(page, 30);
    expect(await draws(page)).toBe(before);
    await setHidden(false);
    await untilDrawsAfter(page, before);
    await page.close();
  });
});

describe('compile only what is shown (the sources WebGL actually compiles)', () => {
  it('a term switched off is in no compiled shader, and a variant that comes back is not compiled again', async () => {
    const page = await open(browser, 'embed.html?w=fresnel-zones&mode=zones-nv');
    await page.evaluate(() => {
      window.__sources = [];
      const orig = WebGL2RenderingContext.prototype.shaderSource;
      WebGL2RenderingContext.prototype.shaderSource = function recorded(shader, src) {
        window.__sources.push(src);
        return orig.call(this, shader, src);
      };
    });
    // reload the widget's programs under the recorder: a fresh page would race it, so record from here on
    await widget(page, 'fresnel-zones');
    // each change waits until its frames and its zone shares (and their programs) are done drawing
    const change = async (partial) => {
      await page.evaluate((p) => globalThis.__shadingLab.widgets['fresnel-zones'].update(p), partial);
      await untilSteady(page, 'drawCalls');
    };
    await change({ shape: 'torusknot' });
    const sources = () => page.evaluate(() => window.__sources);
    expect((await sources()).join('\n')).not.toMatch(/ndfGGX|visibilitySmith/);
    await change({ mode: 'zones-lh-weighted' });
    const afterWeighted = await sources();
    expect(afterWeighted.some((s) => /float ndfGGX/.test(s))).toBe(true);
    await change({ mode: 'zones-nv' });
    await change({ mode: 'zones-lh-weighted' });
    expect((await sources()).length).toBe(afterWeighted.length);
    await page.close();
  });
});
