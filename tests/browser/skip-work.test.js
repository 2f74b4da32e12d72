// Skip what a scene does not need, measured: WebGL draw calls are counted in the page itself. That an idle page draws
// nothing is checked where every page is loaded under the policy (csp.test.js).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open, settle, widget } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const draws = (page) => page.evaluate(() => window.__drawCalls);

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
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ shape: 'torusknot' }));
    await settle(page, 500);
    const sources = () => page.evaluate(() => window.__sources);
    expect((await sources()).join('\n')).not.toMatch(/ndfGGX|visibilitySmith/);
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ mode: 'zones-lh-weighted' }));
    await settle(page, 2500);
    const afterWeighted = await sources();
    expect(afterWeighted.some((s) => /float ndfGGX/.test(s))).toBe(true);
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ mode: 'zones-nv' }));
    await settle(page, 500);
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ mode: 'zones-lh-weighted' }));
    await settle(page, 2500);
    expect((await sources()).length).toBe(afterWeighted.length);
    await page.close();
  });
});
