// Phones and the projector: the Share dialog of every widget (what it links to, its link and QR code, from the
// keyboard), and touch on a 3-D view (dragging moves the light, a tap probes).
import jsQR from 'jsqr';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, getState, launchBrowser, open, setControl, untilIdle, widget } from './helpers.js';

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
  /** Opens the Share dialog of `root` from the keyboard; returns the link shown once its QR code is drawn. */
  async function openShare(page, root) {
    await page.focus(`${root} .share-button`);
    await page.keyboard.press('Enter');
    await page.waitForSelector('dialog.share-dialog[open][data-ready]', { timeout: WAIT_MS });
    return page.$eval('.share-link', (i) => i.value);
  }

  it(
    'every widget of a chapter has one at its top, whose label says it links to the chapter at this state; ' +
      'its QR code decodes to that link, and the dialog offers the widget alone too',
    async () => {
      const page = await open(browser, 'fresnel.html', { width: 1280, height: 900 }); // the QR code's size is a claim
      await widget(page, 'zones');
      const bars = await page.$$eval('.widget', (ws) =>
        ws.map((w) => {
          const button = w.querySelector(':scope > .widget-share .share-button');
          const bar = button?.parentElement.getBoundingClientRect();
          const body = w.querySelector(':scope > .widget-body').getBoundingClientRect();
          return { label: button?.textContent, above: !!bar && bar.bottom <= body.top };
        }),
      );
      expect(bars.length).toBe(4);
      for (const bar of bars) expect(bar).toEqual({ label: 'Share: this chapter at this state', above: true });
      await setControl(page, 'Mode', 'Zones of l·h', '.widget-fresnel-zones');
      await setControl(page, 'Shape', 'Torus knot', '.widget-fresnel-zones');
      const state = await getState(page, 'zones');

      // the default: the chapter, this widget's state in its keys, scrolled to the widget's section
      const link = await openShare(page, '.widget-fresnel-zones');
      expect(await page.evaluate(() => document.activeElement.closest('dialog') !== null)).toBe(true); // focus moved in
      const chapter = new URL(link);
      expect(chapter.pathname).toMatch(/\/fresnel\.html$/);
      expect(chapter.hash).toBe('#zones');
      expect(chapter.searchParams.get('zones.mode')).toBe('zones-lh');
      expect(await decodeQr(page, '.share-qr')).toBe(link);
      const size = await page.$eval('.share-qr', (c) => c.getBoundingClientRect().width);
      expect(size).toBeGreaterThanOrEqual(400); // at 1280 × 900: large enough to scan off a projector

      // the other choice: the widget alone
      await page.click('.share-choices input[value="widget"]');
      await page.waitForFunction(() => document.querySelector('.share-link').value.includes('embed.html'));
      const alone = await page.$eval('.share-link', (i) => i.value);
      expect(new URL(alone).searchParams.get('w')).toBe('fresnel-zones');
      await expect.poll(() => decodeQr(page, '.share-qr'), { timeout: WAIT_MS }).toBe(alone);

      await page.keyboard.press('Escape');
      await page.waitForFunction(() => !document.querySelector('dialog.share-dialog'));
      // focus back
      expect(await page.evaluate(() => document.activeElement.classList.contains('share-button'))).toBe(true);

      // each link opens that state: the chapter's in the chapter, the widget's alone
      const inChapter = await open(browser, link);
      await widget(inChapter, 'zones');
      expect(await getState(inChapter, 'zones')).toEqual(state);
      const opened = await open(browser, alone);
      await widget(opened, 'fresnel-zones');
      expect(await getState(opened, 'fresnel-zones')).toEqual(state);
      expect(page.errors).toEqual([]);
      expect(inChapter.errors).toEqual([]);
      expect(opened.errors).toEqual([]);
      await inChapter.close();
      await opened.close();
      await page.close();
    },
  );

  it('where the page is not the widget’s chapter (here the embed) the label says it links to the widget', async () => {
    const page = await open(browser, 'embed.html?w=ndf-explorer&hwhm=12');
    await widget(page, 'ndf-explorer');
    expect(await page.$eval('.share-button', (b) => b.textContent)).toBe('Share: this widget');
    const link = await openShare(page, '.widget-ndf-explorer');
    expect(await page.$('.share-choices')).toBeNull(); // one link only
    expect(new URL(link).searchParams.get('hwhm')).toBe('12');
    expect(page.errors).toEqual([]);
    await page.close();
  });
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
      await untilIdle(page); // the drag's frames and the figures after it
      const dragged = await getState(page, 'fresnel-zones');
      // touches land on whole pixels and the centre may lie between two: 80 px right of it, up to atan(0.5/80) = 0.36°
      expect(Math.abs(dragged.lightPhi)).toBeLessThan(0.36);
      expect(dragged.lightTheta).toBeGreaterThan(0);

      await page.touchscreen.tap(cx, cy);
      await untilIdle(page); // the probe's frame
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
