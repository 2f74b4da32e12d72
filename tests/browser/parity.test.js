// GLSL against float64: parity.html runs every shader function of the app on the GPU over its domain and
// compares it with its float64 JS twin (src/core/gpu/parity harness); here the page's verdict is read back.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('GLSL vs JS parity', () => {
  it('every shader function matches its float64 twin within the documented tolerance', async () => {
    const page = await open(browser, 'parity.html');
    await page.waitForSelector('#parity-summary', { timeout: 60_000 });
    const results = await page.evaluate(() => globalThis.__shadingLab.parity);
    for (const r of results)
      console.log(
        `parity ${r.name.padEnd(30)} n=${String(r.count).padStart(5)} maxAbs=${r.maxAbs.toExponential(2)} ` +
          `maxRel=${r.maxRel.toExponential(2)} invalid=${r.invalid}`,
      );
    for (const r of results) {
      expect(r.invalid, r.name).toBe(0);
      expect(r.failures, r.name).toBe(0);
    }
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
