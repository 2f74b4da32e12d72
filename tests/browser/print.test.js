// Paper: a chapter page printed by Chromium (page.pdf, which fires beforeprint as a real print does): each widget
// a still of its current state with the state's link and QR code, controls hidden; the PDF rendered to PNG
// (poppler's pdftoppm) holds the still.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import jsQR from 'jsqr';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ZONE_PALETTES } from '../../src/core/ui/palettes.js';
import { sphereZoneFractions } from '../../src/math/zones.js';
import { launchBrowser, open, settle, widget, withPixels } from './helpers.js';

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

describe('a printed chapter page', () => {
  it(
    'shows each widget as a still of its state (zone shares of n·v on the orthographic sphere: sin²45°, ' +
      'sin²75° − sin²45°, cos²75°) with its link and QR code, no controls',
    async () => {
      const page = await open(browser, 'fresnel.html?zones.mode=zones-nv', { width: 1100, height: 900 });
      await widget(page, 'zones');
      await page.$eval('.widget-fresnel-zones', (el) => el.scrollIntoView());
      await settle(page, 800);
      const pdf = await page.pdf({ format: 'A4', printBackground: true });
      writeFileSync(join(dir, 'page.pdf'), pdf);

      const widgets = await page.$$eval('.widget', (ws) => ws.map((w) => w.dataset.widget));
      const stills = await page.$$eval('.widget > .print-still', (fs) =>
        fs.map((f) => ({ img: f.querySelector('img')?.src ?? null, link: f.querySelector('a').href })),
      );
      expect(stills.length).toBe(widgets.length);
      const zones = stills[widgets.indexOf('fresnel-zones')];
      expect(new URL(zones.link).searchParams.get('mode')).toBe('zones-nv');
      const shares = await zoneShares(page, zones.img.split(',')[1]);
      // ±0.05: the silhouette's edge pixels
      sphereZoneFractions().forEach((f, i) => expect(shares[i]).toBeCloseTo(f, 1));

      // each QR code decodes (jsQR, an independent decoder) to its link
      const qrs = await page.$$eval('.print-still .print-qr', (cs) =>
        cs.map((c) => {
          const image = c.getContext('2d').getImageData(0, 0, c.width, c.height);
          return { width: c.width, height: c.height, data: Array.from(image.data) };
        }),
      );
      expect(qrs.map((q) => jsQR(Uint8ClampedArray.from(q.data), q.width, q.height)?.data)).toEqual(
        stills.map((s) => s.link),
      );

      // in print media: the stills show, the controls, share buttons and live views do not
      await page.emulateMediaType('print');
      // laid out at all
      const shown = (sel) => page.$$eval(sel, (els) => els.some((e) => e.getClientRects().length > 0));
      expect(await shown('.print-still')).toBe(true);
      for (const sel of ['.widget-controls', '.lil-gui', '.share-button', '.viewport', '.toolbar'])
        expect(await shown(sel), sel).toBe(false);

      // the PDF, rendered: somewhere on its pages are the still's zone colours
      execFileSync('pdftoppm', ['-r', '40', '-png', join(dir, 'page.pdf'), join(dir, 'p')]);
      const pngs = readdirSync(dir)
        .filter((f) => f.endsWith('.png'))
        .sort();
      expect(pngs.length).toBeGreaterThan(1);
      const printed = [];
      for (const f of pngs) printed.push(await zoneShares(page, readFileSync(join(dir, f)).toString('base64')));
      const withZones = printed.filter((s) => s.every((x) => x > 0.02));
      expect(withZones.length).toBeGreaterThanOrEqual(1);
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );
});
