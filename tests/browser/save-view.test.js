// Every described view saves as PNG (src/core/framework/save-view.js): its button, pressed from the keyboard,
// downloads a PNG of the canvas's own pixel size that matches what the page shows (an element screenshot of the
// canvas, taken by Chromium's compositor, not by our code). One WebGL view (the 3-D lobe, whose drawing buffer
// is cleared after each frame: it must be redrawn before it is read) and one 2-D canvas (the polar plot).
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, allowDownloads, launchBrowser, open, widget } from './helpers.js';

let browser;
let page;
let dir;
beforeAll(async () => {
  browser = await launchBrowser();
  dir = mkdtempSync(join(tmpdir(), 'shading-lab-save-'));
  page = await open(browser, 'embed.html?w=brdf-lobe');
  await allowDownloads(page, dir);
  await widget(page, 'brdf-lobe'); // and idle: every view drawn
});
afterAll(async () => {
  await browser?.close();
  rmSync(dir, { recursive: true, force: true });
});

/** The width and height in a PNG's IHDR chunk (bytes 16–23), after checking the signature. */
function pngSize(bytes) {
  expect([...bytes.subarray(0, 8)]).toEqual([137, 80, 78, 71, 13, 10, 26, 10]);
  expect(bytes.toString('latin1', 12, 16)).toBe('IHDR');
  return [bytes.readUInt32BE(16), bytes.readUInt32BE(20)];
}

/**
 * In the page: both base64 PNGs scaled to 64 × 48 (averaging), the mean absolute difference per channel
 * (0…255), and the share of the saved image's pixels that differ from its most common colour.
 */
const compare = (saved, shown) =>
  page.evaluate(
    async (a, b) => {
      const pixels = async (png) => {
        const bytes = Uint8Array.from(atob(png), (ch) => ch.charCodeAt(0));
        const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }), {
          resizeWidth: 64,
          resizeHeight: 48,
          resizeQuality: 'high',
        });
        const ctx = new OffscreenCanvas(64, 48).getContext('2d');
        ctx.drawImage(bitmap, 0, 0);
        return ctx.getImageData(0, 0, 64, 48).data;
      };
      const [p, q] = [await pixels(a), await pixels(b)];
      let diff = 0;
      const counts = new Map();
      for (let i = 0; i < p.length; i += 4) {
        for (let k = 0; k < 3; k++) diff += Math.abs(p[i + k] - q[i + k]);
        const key = (p[i] >> 3) * 1024 + (p[i + 1] >> 3) * 32 + (p[i + 2] >> 3);
        counts.set(key, (counts.get(key) ?? 0) + 1);
      }
      const n = p.length / 4;
      return { meanDiff: diff / (3 * n), varied: 1 - Math.max(...counts.values()) / n };
    },
    saved,
    shown,
  );

/** Saves the view named `name` from the keyboard and returns { file, bytes, canvasSize, shown }. */
async function saveView(name) {
  const button = await page.$(`.save-view[aria-label="Save image (PNG): ${name}"]`);
  expect(button, `a save button named for "${name}"`).not.toBeNull();
  const canvas = await button.evaluateHandle((b) => b.previousElementSibling);
  const canvasSize = await canvas.evaluate((c) => [c.width, c.height]);
  await page.evaluate(() => document.querySelectorAll('.save-view').forEach((b) => (b.style.visibility = 'hidden')));
  const shown = await canvas.screenshot({ encoding: 'base64' });
  await page.evaluate(() => document.querySelectorAll('.save-view').forEach((b) => (b.style.visibility = '')));
  await button.focus();
  await page.keyboard.press('Enter');
  const file = join(dir, `brdf-lobe-${name.toLowerCase().replace(/[^\p{L}\p{N}]+/gu, '-')}.png`);
  await expect
    .poll(() => existsSync(file), { message: `${file} downloaded`, timeout: WAIT_MS, interval: 100 })
    .toBe(true);
  return { bytes: readFileSync(file), canvasSize, shown };
}

describe('saving a view as PNG', () => {
  for (const [kind, name] of [
    ['a WebGL view', '3-D lobe of A'],
    ['a 2-D canvas', 'Polar plot in the plane of incidence'],
  ]) {
    it(`${kind} (${name}): a PNG of the canvas's pixel size that matches a compositor screenshot of it`, async () => {
      const { bytes, canvasSize, shown } = await saveView(name);
      expect(pngSize(bytes)).toEqual(canvasSize);
      const { meanDiff, varied } = await compare(bytes.toString('base64'), shown);
      expect(varied, 'share of pixels unlike the most common colour').toBeGreaterThan(0.02);
      expect(meanDiff, 'mean difference from the screenshot, per channel').toBeLessThan(6);
    });
  }
});
