// Phones and the projector: the Share dialog of every widget (its link and QR code, from the keyboard), and
// touch on a 3-D view (dragging moves the light, a tap probes).
import jsQR from 'jsqr';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { getState, launchBrowser, open, setControl, settle, widget } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** The text of the QR code drawn on `selector`'s canvas, decoded by jsQR (an independent decoder). */
async function decodeQr(page, selector) {
  const { width, height, data } = await page.$eval(selector, (c) => {
    const image = c.getContext('2d').getImageData(0, 0, c.width, c.height);
    return { width: image.width, height: image.height, data: Array.from(image.data) };
  });
  return jsQR(Uint8ClampedArray.from(data), width, height)?.data ?? null;
}

describe('Share', () => {
  it(
    'every widget of a chapter has one; ' +
      'from the keyboard it opens a dialog whose QR code decodes to the link of the exact state',
    async () => {
      const page = await open(browser, 'fresnel.html');
      await widget(page, 'zones');
      expect(
        await page.$$eval('.widget', (ws) => ws.every((w) => w.querySelector(':scope > .widget-share .share-button'))),
      ).toBe(true);
      await setControl(page, 'Mode', 'Zones of l·h', '.widget-fresnel-zones');
      await setControl(page, 'Shape', 'Torus knot', '.widget-fresnel-zones');
      const state = await getState(page, 'zones');

      await page.focus('.widget-fresnel-zones .share-button');
      await page.keyboard.press('Enter');
      await page.waitForSelector('dialog.share-dialog[open][data-ready]', { timeout: 15_000 });
      expect(await page.evaluate(() => document.activeElement.closest('dialog') !== null)).toBe(true); // focus moved in
      const link = await page.$eval('.share-link', (i) => i.value);
      expect(new URL(link).searchParams.get('w')).toBe('fresnel-zones');
      expect(await decodeQr(page, '.share-qr')).toBe(link);
      const size = await page.$eval('.share-qr', (c) => c.getBoundingClientRect().width);
      expect(size).toBeGreaterThanOrEqual(400); // at 1280 × 900: large enough to scan off a projector

      await page.keyboard.press('Escape');
      await page.waitForFunction(() => !document.querySelector('dialog.share-dialog'));
      // focus back
      expect(await page.evaluate(() => document.activeElement.classList.contains('share-button'))).toBe(true);

      const opened = await open(browser, link);
      await widget(opened, 'fresnel-zones');
      expect(await getState(opened, 'fresnel-zones')).toEqual(state);
      expect(page.errors).toEqual([]);
      expect(opened.errors).toEqual([]);
      await opened.close();
      await page.close();
    },
  );
});

describe('touch', () => {
  const touchPage = (path) =>
    open(browser, path, { width: 800, height: 900 }).then(async (page) => {
      await page.setViewport({ width: 800, height: 900, hasTouch: true });
      return page;
    });

  it(
    'a drag moves the light (right of centre: φ = 0°); ' +
      'a tap at the centre of the orthographic sphere reads n·v = 1',
    async () => {
      const page = await touchPage('embed.html?w=fresnel-zones&mode=zones-lh'); // a mode the light matters to
      await widget(page, 'fresnel-zones');
      const box = await (await page.$('.widget-fresnel-zones canvas')).boundingBox();
      const [cx, cy] = [box.x + box.width / 2, box.y + box.height / 2];
      await page.touchscreen.touchStart(cx, cy - 40);
      for (let i = 1; i <= 5; i++) await page.touchscreen.touchMove(cx + 16 * i, cy);
      await page.touchscreen.touchEnd();
      await settle(page, 300);
      const dragged = await getState(page, 'fresnel-zones');
      expect(dragged.lightPhi).toBeCloseTo(0, 5);
      expect(dragged.lightTheta).toBeGreaterThan(0);

      await page.touchscreen.tap(cx, cy);
      await settle(page, 300);
      const rows = await page.$$eval('.probe tr', (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
      const nv = rows.find(([k]) => k.includes('n·v'));
      expect(nv, JSON.stringify(rows)).toBeDefined();
      expect(Number.parseFloat(nv[1])).toBeCloseTo(1, 3);
      expect((await getState(page, 'fresnel-zones')).lightTheta).toBeCloseTo(0, 0); // the tap also put the light there
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );
});
