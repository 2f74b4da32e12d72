// Failures kept in their box: a widget whose chunk does not arrive (the request aborted, as on a flaky network or a
// redeploy under an open page) or whose create throws says so in its own place with Retry, and the page's other
// widgets still mount; a language tag Intl rejects (WebKitGTK under LANG=C) does not stop the plots; embed.html
// says what to do when its scripts are refused (a sandboxed frame without CORS), with no script of its own.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { SMALL_VIEWPORT, openPage } from './harness.js';
import { WAIT_MS, baseUrl, frameShowing, launchBrowser, otherOrigin } from './helpers.js';
import { WIDGETS } from '../../src/widgets/registry.js';

let browser;
// each page in a context of its own: no service worker of an earlier page serves the chunk that is to be aborted;
// in the small window (no claim here is about a size: SwiftShader draws every pixel on the CPU)
const open = async (path, options) =>
  openPage(await browser.createBrowserContext(), baseUrl(), path, { ...SMALL_VIEWPORT, timeout: WAIT_MS, ...options });
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/**
 * Opens `path` with every request for the built chunk of widget `chunk` aborted until `let()` is called, as a
 * network that drops one file. Returns the page and `let`.
 */
async function openWithoutChunk(path, chunk) {
  let blocked = true;
  const pattern = new RegExp(`/assets/(${chunk})-[\\w-]{8}\\.js$`);
  const page = await open(path, {
    beforeLoad: async (p) => {
      await p.setRequestInterception(true);
      p.on('request', (r) => (blocked && pattern.test(r.url()) ? r.abort('failed') : r.continue()));
    },
  });
  return { page, let: () => (blocked = false) };
}

const mounted = (page) => page.evaluate(() => Object.keys(globalThis.__shadingLab?.widgets ?? {}).sort());
const untilMounted = (page, keys) =>
  page.waitForFunction(
    (keys) => keys.every((k) => globalThis.__shadingLab?.widgets?.[k]),
    { timeout: WAIT_MS, polling: 250 },
    keys,
  );

/** The failure box in `selector`: its words, once it is there. */
async function failureIn(page, selector) {
  const box = await page.waitForSelector(`${selector} .widget-failure`, { timeout: WAIT_MS });
  return box.evaluate((el) => el.innerText);
}

/** What the page reported that is not the aborted chunk itself (its failed request, the browser's own line). */
const otherErrors = (page, chunk) =>
  page.errors.filter((e) => !e.includes(chunk) && !/net::ERR_FAILED|Failed to load resource/.test(e));

describe('a widget that fails stays in its box', () => {
  it('fresnel.html: an aborted chunk shows what failed and Retry; the two others mount; Retry loads it', async () => {
    const { page, let: allow } = await openWithoutChunk('fresnel.html', 'fresnel-curves');
    const words = await failureIn(page, '[data-slot="fresnel-curves"]');
    expect(words).toMatch(/Fresnel curves did not arrive/);
    expect(words).toMatch(/Retry/);
    await untilMounted(page, ['zones', 'tables']);
    expect(await mounted(page)).not.toContain('curves');
    expect(otherErrors(page, 'fresnel-curves')).toEqual([]);
    allow();
    await page.click('[data-slot="fresnel-curves"] .widget-failure button');
    await untilMounted(page, ['curves']);
    expect(await page.$('[data-slot="fresnel-curves"] .widget-failure')).toBeNull();
    expect(await page.$$eval('[data-slot="fresnel-curves"] canvas', (c) => c.length)).toBeGreaterThan(0);
    await page.close();
  });

  it('a chapter page: a create that throws shows its error in place; the rest of the page mounts', async () => {
    // the first ResizeObserver made on the page throws: a real exception inside a widget's create
    const page = await open('brdf.html', {
      beforeLoad: (p) =>
        p.evaluateOnNewDocument(() => {
          const Real = window.ResizeObserver;
          let first = true;
          window.ResizeObserver = class extends Real {
            constructor(callback) {
              if (first) {
                first = false;
                throw new Error('test: the first ResizeObserver throws');
              }
              super(callback);
            }
          };
        }),
    });
    const slots = await page.$$eval('[data-slot]', (s) => s.map((e) => e.dataset.prefix || e.dataset.slot));
    expect(slots.length).toBeGreaterThan(1);
    await page.waitForSelector('.widget-failure', { timeout: WAIT_MS });
    await untilMounted(page, slots.slice(1));
    const boxes = await page.$$eval('.widget-failure', (b) => b.map((e) => e.innerText));
    expect(boxes).toHaveLength(1);
    expect(boxes[0]).toMatch(/could not start[\s\S]*test: the first ResizeObserver throws/);
    await page.click('.widget-failure button');
    await untilMounted(page, slots);
    expect(await page.$('.widget-failure')).toBeNull();
    await page.close();
  });

  it('the tour: a step whose widget does not arrive says so on the stage; Retry and the next step work', async () => {
    const { page, let: allow } = await openWithoutChunk('tour.html#fresnel-zones-nv', 'fresnel-zones');
    expect(await failureIn(page, '.tour-stage')).toMatch(/Fresnel zones did not arrive/);
    expect(otherErrors(page, 'fresnel-zones')).toEqual([]);
    allow();
    await page.click('.tour-stage .widget-failure button');
    await page.waitForFunction(() => globalThis.__shadingLab.widgets.tour, { timeout: WAIT_MS });
    await page.click('.tour-next');
    await page.waitForFunction(() => globalThis.__shadingLab.tour?.ready && location.hash !== '#fresnel-zones-nv', {
      timeout: WAIT_MS,
    });
    expect(await page.$('.tour-stage .widget-failure')).toBeNull();
    await page.close();
  });

  it('embed.html: an aborted chunk shows the failure in the frame, with Retry', async () => {
    const { page, let: allow } = await openWithoutChunk('embed.html?w=fresnel-curves', 'fresnel-curves');
    expect(await failureIn(page, '#embed')).toMatch(/Fresnel curves did not arrive/);
    allow();
    await page.click('#embed .widget-failure button');
    await untilMounted(page, ['fresnel-curves']);
    await page.close();
  });

  it('wall.html: the tiles whose chunks do not arrive say so; every other tile mounts', async () => {
    // the chunks of six of the wall's seven widgets are aborted; the two media tiles mount (media is not aborted: a
    // chunk of shared code, src/math/media.js, has the same name). Surfaces is aborted too: each of its three tiles
    // prefilters a room for its spheres (three.js PMREM) as it mounts, 15 to 27 s a tile in SwiftShader under load
    const blocked = ['fresnel-zones', 'brdf-lobe', 'ndf-explorer', 'visibility-explorer', 'energy', 'surfaces'];
    const { page } = await openWithoutChunk('wall.html', blocked.join('|'));
    await page.waitForFunction(
      () => {
        const tiles = [...document.querySelectorAll('.wall-tile')];
        return tiles.length >= 20 && tiles.every((t) => t.querySelector('[data-widget], .widget-failure'));
      },
      { timeout: WAIT_MS, polling: 250 },
    );
    const titles = await page.$$eval('.wall-tile h2', (h) => h.map((e) => e.textContent));
    const names = titles.map((t) => Object.keys(WIDGETS).find((n) => t.includes(`${WIDGETS[n].title}:`)));
    const up = names.flatMap((n, i) => (blocked.includes(n) ? [] : [`tile${i + 1}`]));
    expect(up.length).toBeGreaterThan(1);
    await untilMounted(page, up);
    expect(await mounted(page)).toEqual(up.sort());
    expect(await page.$$eval('.wall-tile .widget-failure', (b) => b.length)).toBe(titles.length - up.length);
    await page.close();
  });
});

describe('a library that throws as it loads cannot take the app down', () => {
  it('navigator.language "C" (WebKitGTK under LANG=C; Intl rejects it): the Fresnel plots still draw', async () => {
    const page = await open('fresnel.html', {
      beforeLoad: (p) =>
        p.evaluateOnNewDocument(() => Object.defineProperty(Navigator.prototype, 'language', { get: () => 'C' })),
    });
    await untilMounted(page, ['curves', 'zones', 'tables']);
    expect(await page.$('.widget-failure')).toBeNull();
    expect(await page.$$eval('[data-slot="fresnel-curves"] .uplot', (u) => u.length)).toBeGreaterThan(0);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('embed.html when its scripts are refused', () => {
  /** The fallback's words once it shows, polled from here: a page with scripts off runs no poll of its own. */
  async function fallback(target) {
    const words = () =>
      target.evaluate(() => {
        const box = document.getElementById('embed-fallback');
        return box && getComputedStyle(box).visibility === 'visible' ? box.innerText : null;
      });
    await expect.poll(words, { timeout: WAIT_MS, interval: 250 }).toBeTruthy();
    return words();
  }

  it('in <iframe sandbox="allow-scripts"> on a host without CORS: the frame says what to do', async () => {
    const page = await open(new URL('index.html', otherOrigin()).href, {
      beforeLoad: (p) => p.setBypassCSP(true),
    });
    await page.evaluate((src) => {
      const frame = Object.assign(document.createElement('iframe'), { src, id: 'embedded' });
      frame.setAttribute('sandbox', 'allow-scripts');
      frame.style.cssText = 'width: 900px; height: 500px; border: 0';
      document.body.replaceChildren(frame);
    }, new URL('embed.html?w=fresnel-curves', baseUrl()).href);
    const frame = await frameShowing(page, '#embedded');
    const words = await fallback(frame);
    expect(words).toMatch(/scripts did not run/);
    expect(words).toMatch(/allow-same-origin/);
    expect(words).toMatch(/Access-Control-Allow-Origin/);
    await page.close();
  });

  it('with scripts turned off: the same words; with them on, the app replaces them at once', async () => {
    const off = await (await browser.createBrowserContext()).newPage();
    await off.setJavaScriptEnabled(false);
    await off.goto(new URL('embed.html?w=fresnel-curves', baseUrl()).href, { timeout: WAIT_MS });
    expect(await fallback(off)).toMatch(/turn them on/);
    await off.close();
    const on = await open('embed.html?w=fresnel-curves');
    await untilMounted(on, ['fresnel-curves']);
    expect(await on.$('#embed-fallback')).toBeNull();
    await on.close();
  });
});
