// Paper: a chapter page printed by Chromium (page.pdf, which fires beforeprint as a real print does): each canvas
// of a widget a still of its current state in its place, the state's link and QR code under the views, controls
// hidden; the PDF rendered to PNG (poppler's pdftoppm) holds the stills, fills its first page and ends on white.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import jsQR from 'jsqr';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ZONE_PALETTES } from '../../src/core/ui/palettes.js';
import { sphereZoneFractions } from '../../src/math/zones.js';
import { launchBrowser, open, untilIdle, widget, withPixels } from './helpers.js';

let browser;
let dir;
beforeAll(async () => {
  browser = await launchBrowser();
  dir = mkdtempSync(join(tmpdir(), 'shading-lab-print-'));
});
afterAll(async () => {
  await browser?.close();
  rmSync(dir, { recursive: true, force: true });
});

const hexToRgb = (hex) => [1, 3, 5].map((i) => Number.parseInt(hex.slice(i, i + 2), 16));
const ZONES = ZONE_PALETTES.talk.colors.map(hexToRgb);

/** Shares of the pixels nearest each zone colour (within 40 per channel), among all such pixels of a base64 PNG. */
const zoneShares = (page, png) =>
  withPixels(
    page,
    png,
    `(image) => {
    const zones = ${JSON.stringify(ZONES)};
    const counts = [0, 0, 0];
    for (let i = 0; i < image.data.length; i += 4) {
      const d = zones.map((z) => Math.max(...z.map((c, k) => Math.abs(c - image.data[i + k]))));
      const best = d.indexOf(Math.min(...d));
      if (d[best] < 40) counts[best]++;
    }
    const total = counts.reduce((a, b) => a + b, 0);
    return counts.map((c) => c / total);
  }`,
  );

/** Of a base64 PNG of a printed page: where its last inked row is (0…1 of the height) and its bottom row's colour. */
const pageInk = (page, png) =>
  withPixels(
    page,
    png,
    `(image) => {
    const { width, height, data } = image;
    const inked = (y) => {
      for (let x = 0; x < width; x++) if (data[(y * width + x) * 4] < 200) return true;
      return false;
    };
    let last = height - 1;
    while (last > 0 && !inked(last)) last--;
    const i = ((height - 1) * width + (width >> 1)) * 4;
    return { lastInk: last / height, bottom: [data[i], data[i + 1], data[i + 2]] };
  }`,
  );

describe('a printed chapter page', () => {
  it(
    'shows each view as a still of its state in its place (zone shares of n·v on the orthographic sphere: sin²45°, ' +
      'sin²75° − sin²45°, cos²75°), the link and QR code under it, no controls; plot titles above their plots, ' +
      'page 1 full, the last page white',
    async () => {
      const page = await open(browser, 'fresnel.html?zones.mode=zones-nv', { width: 1100, height: 900 });
      await widget(page, 'zones');
      await page.$eval('.widget-fresnel-zones', (el) => el.scrollIntoView());
      await untilIdle(page); // the views now in sight drawn
      const pdf = await page.pdf({ format: 'A4', printBackground: true });
      writeFileSync(join(dir, 'page.pdf'), pdf);

      const widgets = await page.$$eval('.widget', (ws) => ws.map((w) => w.dataset.widget));
      const links = await page.$$eval('.widget > .print-link a', (as) => as.map((a) => a.href));
      expect(links.length).toBe(widgets.length);
      const zonesLink = links[widgets.indexOf('fresnel-zones')];
      expect(new URL(zonesLink).searchParams.get('mode')).toBe('zones-nv');
      const zones = await page.$eval('.widget-fresnel-zones img.print-canvas', (img) => img.src);
      const shares = await zoneShares(page, zones.split(',')[1]);
      // ±0.05: the silhouette's edge pixels
      sphereZoneFractions().forEach((f, i) => expect(shares[i]).toBeCloseTo(f, 1));

      // each QR code decodes (jsQR, an independent decoder) to its link
      const qrs = await page.$$eval('.print-link .print-qr', (cs) =>
        cs.map((c) => {
          const image = c.getContext('2d').getImageData(0, 0, c.width, c.height);
          return { width: c.width, height: c.height, data: Array.from(image.data) };
        }),
      );
      expect(qrs.map((q) => jsQR(Uint8ClampedArray.from(q.data), q.width, q.height)?.data)).toEqual(links);

      // in print media: the stills show, the controls, share buttons and live views do not
      await page.emulateMediaType('print');
      // laid out at all
      const shown = (sel) => page.$$eval(sel, (els) => els.some((e) => e.getClientRects().length > 0));
      expect(await shown('.print-canvas')).toBe(true);
      for (const sel of ['.widget-controls', '.lil-gui', '.share-button', '.viewport', '.toolbar'])
        expect(await shown(sel), sel).toBe(false);
      // every plot prints its title, then its still below it, in the print layout
      const plots = await page.$$eval('figure.plot', (figs) =>
        figs.map((f) => {
          const title = f.querySelector('figcaption').getBoundingClientRect();
          const still = f.querySelector('img.print-canvas')?.getBoundingClientRect();
          return { title: f.querySelector('figcaption').textContent, below: !!still && still.top >= title.bottom - 1 };
        }),
      );
      expect(plots.length).toBeGreaterThanOrEqual(2);
      expect(plots.filter((p) => !p.below)).toEqual([]);

      // the PDF, rendered: somewhere on its pages are the still's zone colours
      execFileSync('pdftoppm', ['-r', '40', '-png', join(dir, 'page.pdf'), join(dir, 'p')]);
      const pngs = readdirSync(dir)
        .filter((f) => f.endsWith('.png'))
        .sort();
      expect(pngs.length).toBeGreaterThan(1);
      const printed = [];
      const ink = [];
      for (const f of pngs) {
        const png = readFileSync(join(dir, f)).toString('base64');
        printed.push(await zoneShares(page, png));
        ink.push(await pageInk(page, png));
      }
      const withZones = printed.filter((s) => s.every((x) => x > 0.02));
      expect(withZones.length).toBeGreaterThanOrEqual(1);
      // page 1 is filled down to near its bottom margin (Chromium's 0.4 in of 11.7 in), not left half empty by a
      // figure that went whole to page 2 (it ended at 0.54 of the page so); the paper under the last line of the
      // last page is white, not the screen's tint (#fbfbfa)
      expect(ink[0].lastInk).toBeGreaterThan(0.75);
      expect(ink.at(-1).bottom).toEqual([255, 255, 255]);
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );
});
