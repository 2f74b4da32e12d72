// GLSL against float64: parity.html runs every shader function of the app on the GPU over its domain and
// compares it with its float64 JS twin (src/core/gpu/parity harness); here the page's verdict is read back.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser, open } from './helpers.js';

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
    await page.waitForSelector('#parity-summary', { timeout: WAIT_MS });
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

  it('the report names the GPU as WebGL reports it, and each function with its worst case', async () => {
    const page = await open(browser, 'parity.html?only=srgbToLinear,equirectUv,diffuseOrenNayar');
    await page.waitForSelector('#parity-summary', { timeout: WAIT_MS });
    const { text, results, renderer } = await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      const ext = gl.getExtension('WEBGL_debug_renderer_info');
      return {
        text: document.querySelector('#parity-report').value,
        results: globalThis.__shadingLab.parity,
        renderer: gl.getParameter(ext ? ext.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
      };
    });
    expect(text).toContain(`GL renderer: ${renderer}`);
    expect(text).toContain(`Browser: ${await browser.userAgent()}`);
    expect(text).toContain(`Result: 0 of ${results.length} functions beyond tolerance`);
    expect(results.map((r) => r.name)).toEqual([
      'srgbToLinear',
      'equirectUv',
      'diffuseOrenNayar (grazing, cos φ < 0)',
      'diffuseOrenNayar',
      'diffuseOrenNayarQualitative',
    ]);
    for (const r of results) {
      const line = text.split('\n').find((l) => l.startsWith(`ok   ${r.name}: `));
      expect(line, r.name).toContain(`${r.count} inputs, ${r.failures} beyond tolerance`);
      expect(line).toContain(`GPU ${r.worst.gpu.toPrecision(7)}, JS ${r.worst.js.toPrecision(7)}`);
    }
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
