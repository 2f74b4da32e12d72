// Embedding, the size: a widget in an iframe fills its frame, with no page chrome, and follows the frame's size;
// the <shading-lab-widget> element takes the height the widget reports (its `resize` message), on another origin;
// the presenter view (presenter=1) shows the views only, filling the frame.
import { afterAll, beforeAll, describe, expect, it, onTestFinished } from 'vitest';
import { openPage } from './harness.js';
import { serveDecks } from './decks.js';
import { WAIT_MS, baseUrl, frameShowing, launchBrowser, untilIdle } from './helpers.js';

let browser;
let decks;
beforeAll(async () => {
  browser = await launchBrowser();
  decks = await serveDecks({});
});
afterAll(async () => {
  await browser?.close();
  decks?.close();
});

/** The frame of iframe `selector` in `page`, once its widget is registered. */
async function widgetFrame(page, selector) {
  const frame = await frameShowing(page, selector);
  await frame.waitForFunction(() => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length === 1, {
    timeout: WAIT_MS,
  });
  return frame;
}

describe('embedding', () => {
  it('a widget in an iframe fills the frame and follows its size', async () => {
    const page = await browser.newPage();
    page.setDefaultTimeout(WAIT_MS); // as open() does: setContent waits for the frame's load too
    const url = new URL('embed.html?w=fresnel-zones', baseUrl()).href;
    await page.setContent(`<iframe id="f" src="${url}" style="width:480px;height:420px;border:0"></iframe>`);
    const frame = await widgetFrame(page, '#f');
    await untilIdle(frame); // laid out and drawn at the frame's size
    const width = () => frame.$eval('.widget-fresnel-zones canvas', (c) => c.getBoundingClientRect().width);
    const w1 = await width();
    expect(w1).toBeGreaterThan(300);
    expect(w1).toBeLessThanOrEqual(480);
    expect(await frame.$('.site-header')).toBeNull(); // no page chrome
    await page.$eval('#f', (f) => (f.style.width = '720px')); // still one column (the controls move below under 760 px)
    // the canvas takes the new width when the widget's resize observer has run: polled for, not waited a time
    await expect.poll(width, { timeout: WAIT_MS }).toBeGreaterThan(w1 * 1.3);
    await page.close();
  });

  it(
    'the element on another origin grows to the height the widget reports, the probe table included: ' +
      'no scroll bar inside, the zone legend in sight',
    async () => {
      const lab = encodeURIComponent(new URL('embed.html', baseUrl()).href);
      const page = await openPage(browser, decks.url, `/examples/element/index.html?lab=${lab}`, {
        width: 1280,
        height: 800,
        timeout: WAIT_MS,
      });
      onTestFinished(() => page.close().catch(() => {}));
      await page.waitForFunction(() => document.getElementById('zones').ready, { timeout: WAIT_MS });
      const frame = await widgetFrame(page, '#zones iframe');
      // the frame's own measure of its content, against the element's height in the page
      const fits = () =>
        Promise.all([
          page.$eval('#zones', (el) => el.getBoundingClientRect().height),
          frame.evaluate(() => {
            const legend = document.querySelector('.zone-legend').getBoundingClientRect();
            const root = document.documentElement;
            return { content: root.scrollHeight, inside: innerHeight, legendBottom: legend.bottom };
          }),
        ]).then(([element, f]) => ({
          element,
          grown: element > 600,
          noScroll: f.content <= f.inside,
          legendInSight: f.legendBottom <= f.inside,
        }));
      await expect.poll(fits, { timeout: WAIT_MS }).toMatchObject({ grown: true, noScroll: true, legendInSight: true });
      const before = (await fits()).element;

      // the pointer on the sphere: the probe's table appears under the view, and the element grows with it. The
      // sphere's place is measured again at each try: the element may still be growing (once seen to move the
      // canvas away from a point measured once, in CI)
      const pointAtSphere = async () => {
        const box = await (await page.$('#zones')).boundingBox();
        const canvas = await frame.$eval('.widget-fresnel-zones canvas', (c) => {
          const r = c.getBoundingClientRect();
          return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
        });
        await page.mouse.move(box.x + canvas.x, box.y + canvas.y);
        return frame.evaluate(() => Boolean(document.querySelector('.probe table')));
      };
      await expect.poll(pointAtSphere, { timeout: WAIT_MS }).toBe(true);
      await expect
        .poll(fits, { timeout: WAIT_MS })
        .toMatchObject({ noScroll: true, legendInSight: true, element: expect.toSatisfy((h) => h > before) });
      expect(page.errors).toEqual([]);
    },
  );

  it('the presenter view (presenter=1) has no control panel and its 3-D view fills the frame', async () => {
    const page = await browser.newPage();
    page.setDefaultTimeout(WAIT_MS);
    onTestFinished(() => page.close().catch(() => {}));
    const url = new URL('embed.html?w=fresnel-zones&presenter=1', baseUrl()).href;
    await page.setContent(`<iframe id="f" src="${url}" style="width:960px;height:540px;border:0"></iframe>`);
    const frame = await widgetFrame(page, '#f');
    const layout = () =>
      frame.evaluate(() => {
        const shown = (sel) => [...document.querySelectorAll(sel)].some((e) => e.getClientRects().length > 0);
        const view = document.querySelector('.viewport').getBoundingClientRect();
        const main = document.querySelector('main');
        return {
          controls: shown('.lil-gui, .widget-controls, .share-button, .save-view'),
          viewShare: (view.width * view.height) / (innerWidth * innerHeight),
          viewWidth: view.width / innerWidth,
          scrolls: main.scrollHeight > main.clientHeight || document.documentElement.scrollHeight > innerHeight,
        };
      });
    await expect.poll(layout, { timeout: WAIT_MS }).toMatchObject({ controls: false, viewWidth: 1, scrolls: false });
    // the rest below the view is the zone legend, a sixth of the frame at most
    expect((await layout()).viewShare).toBeGreaterThan(0.8);
    // the whole state still comes from the URL, and the URL written back keeps presenter=1
    await frame.evaluate(() => Object.values(globalThis.__shadingLab.widgets)[0].update({ mode: 'zones-lh' }));
    await frame.waitForFunction(() => new URL(location.href).searchParams.get('mode') === 'zones-lh');
    expect(new URL(frame.url()).searchParams.get('presenter')).toBe('1');
  });
});
