// Embedding, the size: a widget in an iframe fills its frame, with no page chrome, and follows the frame's size.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { baseUrl, launchBrowser, settle } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('embedding', () => {
  it('a widget in an iframe fills the frame and follows its size', async () => {
    const page = await browser.newPage();
    const url = new URL('embed.html?w=fresnel-zones', baseUrl()).href;
    await page.setContent(`<iframe id="f" src="${url}" style="width:480px;height:420px;border:0"></iframe>`);
    const frame = await (await page.waitForSelector('#f')).contentFrame();
    await frame.waitForFunction(() => globalThis.__shadingLab?.widgets?.['fresnel-zones'], { timeout: 30_000 });
    await settle(page, 800);
    const width = () => frame.$eval('.widget-fresnel-zones canvas', (c) => c.getBoundingClientRect().width);
    const w1 = await width();
    expect(w1).toBeGreaterThan(300);
    expect(w1).toBeLessThanOrEqual(480);
    expect(await frame.$('.site-header')).toBeNull(); // no page chrome
    await page.$eval('#f', (f) => (f.style.width = '720px')); // still one column (the controls move below under 760 px)
    await settle(page, 800);
    expect(await width()).toBeGreaterThan(w1 * 1.3);
    await page.close();
  });
});
