// The suite's browsers (harness.js, launchBrowser): the files of a worker share one Chromium, each in an incognito
// context of its own, so that nothing a file stores is seen by the next; a Chromium that went away is replaced.
import { afterEach, describe, expect, inject, it } from 'vitest';
import { WAIT_MS, baseUrl, launchBrowser } from './helpers.js';

const opened = [];
afterEach(async () => {
  await Promise.all(opened.splice(0).map((b) => b.close()));
});

/** A browser as a test file gets it (closed after the test). */
async function fileBrowser() {
  const browser = await launchBrowser();
  opened.push(browser);
  return browser;
}

/** Opens `path` of the app (the landing page, whose script registers the service worker); resolves to the page. */
async function landing(browser, path = 'index.html') {
  const page = await browser.newPage();
  await page.goto(new URL(path, baseUrl()).href, { waitUntil: 'load', timeout: WAIT_MS });
  return page;
}

/** A document of the app's origin that runs none of its scripts (so registers no service worker of its own). */
const PLAIN = 'exercises/index.json';

/** Leaves a mark in every store a page has: localStorage, a cookie, Cache Storage, IndexedDB. */
const mark = (page) =>
  page.evaluate(async () => {
    localStorage.setItem('harness-mark', '1');
    document.cookie = 'harnessMark=1; max-age=600';
    await (await caches.open('harness-mark')).put('harness-mark', new Response('1'));
    await new Promise((ok, fail) => {
      const req = indexedDB.open('harness-mark');
      req.onsuccess = () => (req.result.close(), ok());
      req.onerror = () => fail(req.error);
    });
  });

/** Which of mark()'s stores hold a mark, and how many service workers the origin has. */
const marks = (page) =>
  page.evaluate(async () => ({
    localStorage: localStorage.getItem('harness-mark') !== null,
    cookie: document.cookie.includes('harnessMark=1'),
    caches: (await caches.keys()).includes('harness-mark'),
    indexedDB: (await indexedDB.databases()).some((d) => d.name === 'harness-mark'),
    serviceWorkers: (await navigator.serviceWorker.getRegistrations()).length,
  }));

const NONE = { localStorage: false, cookie: false, caches: false, indexedDB: false, serviceWorkers: 0 };

describe('one Chromium per worker, an incognito context per file', () => {
  it('two files of a worker share its Chromium (one DevTools address) but not their pages', async () => {
    const [a, b] = [await fileBrowser(), await fileBrowser()];
    const [pa, pb] = [await landing(a), await landing(b)];
    expect(pa.browser().wsEndpoint()).toBe(pb.browser().wsEndpoint());
    expect(pa.browserContext()).not.toBe(pb.browserContext());
    expect((await a.pages()).length).toBe(1);
  });

  it(
    'what a file stored (local storage, cookie, cache, IndexedDB, service worker) is gone for the next file, ' +
      'and kept within the file',
    async () => {
      const first = await fileBrowser();
      const page = await landing(first);
      await mark(page);
      // the app registers its service worker on the first visit (src/core/offline)
      await page.waitForFunction(async () => (await navigator.serviceWorker.getRegistrations()).length > 0, {
        timeout: WAIT_MS,
      });
      const again = await landing(first, PLAIN); // the same file: its marks are there (the probe can see them)
      expect(await marks(again)).toEqual({
        ...NONE,
        localStorage: true,
        cookie: true,
        caches: true,
        indexedDB: true,
        serviceWorkers: 1,
      });
      await first.close();

      const next = await landing(await fileBrowser(), PLAIN);
      expect(await marks(next)).toEqual(NONE);
    },
  );

  it('a worker whose Chromium went away (closed, as in a crash) gets a new one, and its file goes on', async () => {
    const browser = await fileBrowser();
    const page = await landing(browser);
    const before = page.browser().wsEndpoint();
    await page.browser().close(); // ends the shared Chromium itself, not only this connection
    const after = await landing(browser); // the same file, after the loss
    expect(after.browser().wsEndpoint()).not.toBe(before);
    expect(await after.evaluate(() => document.readyState)).toBe('complete');
    const later = await landing(await fileBrowser()); // and the next file is given the new one
    expect(later.browser().wsEndpoint()).toBe(after.browser().wsEndpoint());
  });

  it('what a file left open (it ended without closing) is closed before the next file of its worker', async () => {
    const page = await landing(await fileBrowser());
    // the next file is another process: it asks the broker for the worker's Chromium as launchBrowser() does
    const next = `${inject('chromiumBroker')}?worker=${process.env.VITEST_POOL_ID ?? 0}&pid=next-file`;
    expect((await fetch(next)).ok).toBe(true);
    await expect.poll(() => page.isClosed(), { timeout: WAIT_MS }).toBe(true);
  });

  it('a file asking for flags of its own gets a Chromium of its own', async () => {
    const own = await launchBrowser(['--disable-3d-apis']);
    opened.push(own);
    const shared = await landing(await fileBrowser());
    expect(own.wsEndpoint()).not.toBe(shared.browser().wsEndpoint());
    const page = await own.newPage();
    expect(await page.evaluate(() => !!document.createElement('canvas').getContext('webgl2'))).toBe(false);
  });
});
