// The surfaces chapter in a real Chromium: the subsurface-scale widget.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { getState, launchBrowser, open, setControl, shot, untilIdle, widget } from './helpers.js';

// surfaces.html sets up subsurface-scale's random walks on the main thread: seconds on an idle machine, and 36 s
// were seen under a load average of 30, so a test that opens the page has three minutes
const SURFACES_PAGE_MS = 180_000;

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('subsurface-scale', () => {
  it(
    'says diffuse is enough for a large shading sample and subsurface ' + 'scattering is needed for a small one',
    async () => {
      const page = await open(browser, 'surfaces.html');
      await widget(page, 'sss');
      const verdict = () => page.$eval('.verdict', (el) => el.textContent);
      expect(await verdict()).toMatch(/diffuse term is enough/);
      const before = await shot(page, 'canvas.subsurface');
      await setControl(page, 'Shading sample radius (mm)', 0.2);
      expect(await verdict()).toMatch(/subsurface scattering is needed/);
      expect(await shot(page, 'canvas.subsurface')).not.toBe(before);
      const stats = await page.evaluate(() => globalThis.__shadingLab.widgets.sss.getStatistics());
      expect(stats.insideShare).toBeLessThan(0.9);
      expect(stats.reflectance).toBeGreaterThan(0.3);
      expect(stats.reflectance).toBeLessThan(1);
      const url = page.url();
      expect(url).toMatch(/sss\.pixel=0\.2/);
      const again = await open(browser, url.slice(url.indexOf('surfaces.html')));
      await widget(again, 'sss');
      expect(await getState(again, 'sss')).toEqual(await getState(page, 'sss'));
      expect([...page.errors, ...again.errors]).toEqual([]);
      await Promise.all([page.close(), again.close()]);
    },
    SURFACES_PAGE_MS,
  );

  it('more absorption means less light comes back out, and closer to where it went in', async () => {
    const page = await open(browser, 'embed.html?w=subsurface-scale&sigmaA=0');
    await widget(page, 'subsurface-scale');
    const clear = await page.evaluate(() => globalThis.__shadingLab.widgets['subsurface-scale'].getStatistics());
    await page.evaluate(() => globalThis.__shadingLab.widgets['subsurface-scale'].update({ sigmaA: 1 }));
    await untilIdle(page);
    const dark = await page.evaluate(() => globalThis.__shadingLab.widgets['subsurface-scale'].getStatistics());
    console.log(
      `subsurface: σa 0 → reflectance ${clear.reflectance.toFixed(3)}, ` +
        `mean exit ${clear.mean.toFixed(3)} mm; σa 1/mm → ${dark.reflectance.toFixed(3)}, ${dark.mean.toFixed(3)} mm`,
    );
    expect(clear.reflectance).toBeGreaterThan(0.95); // nothing absorbs: (nearly) all of it comes back
    expect(dark.reflectance).toBeLessThan(clear.reflectance / 2);
    expect(dark.mean).toBeLessThan(clear.mean);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('surfaces', () => {
  it(
    'reflects by exact Fresnel, absorbs in metals, and spreads a rough reflection into a cone',
    async () => {
      const page = await open(browser, 'surfaces.html?surf.theta=60');
      await widget(page, 'surf');
      const F = () => page.evaluate(() => globalThis.__shadingLab.widgets.surf.getReflected());
      const glass = await F();
      const before = await shot(page, 'canvas.interface');
      await setControl(page, 'Material', 'Silver');
      const silver = await F();
      expect(silver).toBeGreaterThan(0.9);
      expect(glass).toBeLessThan(0.2);
      expect(await page.$eval('.widget-surfaces .widget-about', (el) => el.textContent)).toMatch(/metal swallows/);
      expect(await shot(page, 'canvas.interface')).not.toBe(before);
      expect(page.errors).toEqual([]);
      await page.close();
    },
    SURFACES_PAGE_MS,
  );
});
