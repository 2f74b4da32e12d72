// The media chapter in a real Chromium: absorption over distance, scattering, the grid, progressive rendering.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, afterFrames, launchBrowser, open, setControl, shot, untilIdle, widget } from './helpers.js';
import { transmittance, waterAbsorptionRgb } from '../../src/math/media.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** Mean linear RGB of the centre of the glass (a pure absorber renders exactly from the first frame). */
async function glassColour(page) {
  const png = await shot(page, '.media-view canvas');
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = new OffscreenCanvas(img.width, img.height);
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(
      Math.round(img.width * 0.3),
      Math.round(img.height * 0.3),
      Math.round(img.width * 0.4),
      Math.round(img.height * 0.4),
    ).data;
    const toLinear = (v) => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4);
    const sum = [0, 0, 0];
    for (let i = 0; i < d.length; i += 4) for (let k = 0; k < 3; k++) sum[k] += toLinear(d[i + k] / 255);
    return sum.map((s) => s / (d.length / 4));
  }, png);
}

describe('media', () => {
  it(
    'keeps water clear over 5 cm and takes the red out over 20 m, ' + 'as Beer-Lambert with Hale & Querry predicts',
    async () => {
      // a pure absorber is exact from its first sample: one is enough, and nothing waits for 64 to converge
      const page = await open(browser, 'media.html?media.distance=-1.3', { maxSamples: 1 });
      await widget(page, 'media');
      const shallow = await glassColour(page);
      await setControl(page, 'Depth, log₁₀ metres', 1.3);
      const deep = await glassColour(page);
      const T = waterAbsorptionRgb().map((s) => transmittance(s, 20));
      console.log(
        `water: 5 cm glass RGB ${shallow.map((x) => x.toFixed(3))}, 20 m ${deep.map((x) => x.toFixed(3))}; ` +
          `predicted ratios R/B ${(T[0] / T[2]).toFixed(4)}, G/B ${(T[1] / T[2]).toFixed(3)}`,
      );
      expect(shallow[0] / shallow[2]).toBeGreaterThan(0.97);
      expect(deep[0] / deep[2]).toBeLessThan(0.02); // predicted 0.0035: the red is gone
      expect(Math.abs(deep[1] / deep[2] - T[1] / T[2])).toBeLessThan(0.03);
      expect(page.url()).toMatch(/media\.distance=1\.3/);
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );

  it('renders the grid and milk progressively, then stops drawing', async () => {
    const page = await open(browser, 'embed.html?w=media&view=grid&samples=16');
    await widget(page, 'media');
    // path tracing in software WebGL: seconds on an idle machine, a minute and more beside other work
    await page.waitForFunction(() => globalThis.__shadingLab.widgets.media.getProgress().frame >= 16, {
      timeout: WAIT_MS,
    });
    await untilIdle(page); // its last frame drawn, and no frame asked for after it
    const before = await page.evaluate(() => window.__drawCalls);
    await afterFrames(page, 30);
    expect(await page.evaluate(() => window.__drawCalls)).toBe(before);
    // milk: high scattering, low absorption: bright and without colour
    await page.evaluate(() => globalThis.__shadingLab.widgets.media.update({ view: 'one', medium: 'milk' }));
    await page.waitForFunction(() => globalThis.__shadingLab.widgets.media.getProgress().frame >= 16, {
      timeout: WAIT_MS,
    });
    const milk = await glassColour(page);
    console.log(`milk (16 samples): glass RGB ${milk.map((x) => x.toFixed(3))}`);
    expect(Math.min(...milk)).toBeGreaterThan(0.35);
    expect(Math.max(...milk) / Math.min(...milk)).toBeLessThan(1.25);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
