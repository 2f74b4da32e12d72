// Offline: after one visit every page, widget and exercise of the build loads with the network gone (the server
// drops every connection and Chromium is set offline); a new deploy is fetched into the cache and announced.
import { cpSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';
import { afterAll, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { ROOT, SMALL_VIEWPORT, SUB_PATH, openPage } from './harness.js';
import { TEST_BUDGET_MS, WAIT_MS, afterFrames, launchBrowser, untilLoaded } from './helpers.js';

const TYPES = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.svg': 'image/svg+xml',
  '.json': 'application/json',
  '.webmanifest': 'application/manifest+json',
};

/** Serves `dir` under SUB_PATH like the harness, with a switch that makes the network fail (connections dropped). */
function serveSwitchable(dir) {
  const state = { online: true };
  const server = createServer((req, res) => {
    if (!state.online) return void req.socket.destroy();
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    let file = normalize(join(dir, path.slice(SUB_PATH.length)));
    if (!path.startsWith(SUB_PATH) || !file.startsWith(dir)) return void res.writeHead(404).end();
    if (path.endsWith('/')) file = join(file, 'index.html');
    try {
      res
        .writeHead(200, {
          'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
          'cache-control': 'no-cache',
        })
        .end(readFileSync(file));
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((ok) =>
    server.listen(0, '127.0.0.1', () =>
      ok({
        state,
        url: `http://127.0.0.1:${server.address().port}${SUB_PATH}`,
        close: () => (server.closeAllConnections(), server.close()),
      }),
    ),
  );
}

let browser;
let dir;
let site;
beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'shading-lab-offline-'));
  cpSync(join(ROOT, 'dist'), dir, { recursive: true }); // a deploy of its own, changed below
  site = await serveSwitchable(dir);
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
  site?.close();
  rmSync(dir, { recursive: true, force: true });
});

const PAGES = readdirSync(join(ROOT, 'dist')).filter((f) => f.endsWith('.html'));
/** A 2-D plot (uPlot), a three.js view (the material lab), a widget with a Web Worker (the measured BRDF's fits). */
const OFFLINE_WIDGETS = ['fresnel-curves', 'material-lab', 'measured-brdf'];
const EXERCISES = JSON.parse(readFileSync(join(ROOT, 'public/exercises/index.json'), 'utf8')).exercises;
/**
 * One exercise of each kind (its widget, or a shader exercise with or without its plot), by id: the list fetches and
 * checks every exercise's file (an exercise whose file failed is not listed), so opening one of a kind shows that
 * kind's code (its widget's chunk, the shader editor and grader) runs from the cache.
 */
const ONE_OF_EACH_KIND = [
  ...new Map(
    EXERCISES.map((file) => JSON.parse(readFileSync(join(ROOT, 'public/exercises', file), 'utf8')))
      .map((e) => [e.widget ?? `${e.kind}${e.plot ? ' with a plot' : ''}`, e.id])
      .toReversed(),
  ).values(),
];

/** Opens `path` of the site (at the small viewport: no test here is about a size); resolves once it has loaded. */
const visit = (path) => openPage(browser, site.url, path, { ...SMALL_VIEWPORT, timeout: WAIT_MS });

async function goOffline(page) {
  site.state.online = false;
  await page.setOfflineMode(true);
}

/** The service worker's precache manifest, [{ url, revision }], as Workbox wrote it into the built sw.js. */
function precacheManifest() {
  const sw = readFileSync(join(ROOT, 'dist/sw.js'), 'utf8');
  const list = /precacheAndRoute\((\[[\s\S]*?\])\s*,\s*\{/.exec(sw);
  expect(list, 'a precacheAndRoute([...], {...}) call in dist/sw.js').not.toBeNull();
  return JSON.parse(list[1]);
}

/** Every file of the built site, relative to dist/ (the list a static host serves, read from the disk). */
const builtFiles = (dir = join(ROOT, 'dist'), prefix = '') =>
  readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? builtFiles(join(dir, e.name), `${prefix}${e.name}/`) : [`${prefix}${e.name}`],
  );

describe('the precache manifest (read in Node from the build of this run)', () => {
  it(
    'lists every file of the build but the service worker and its Workbox runtime, each with a revision or ' +
      'a content hash in its name',
    () => {
      const manifest = precacheManifest();
      const urls = [...new Set(manifest.map((e) => e.url))]; // the icon comes twice: a file, and the app's icon
      const runtime = (f) => f === 'sw.js' || /^workbox-[0-9a-f]{8}\.js$/.test(f);
      expect(urls.sort()).toEqual(
        builtFiles()
          .filter((f) => !runtime(f))
          .sort(),
      );
      const unversioned = manifest.filter((e) => !e.revision && !/-[\w-]{8}\.\w+$/.test(e.url)).map((e) => e.url);
      expect(unversioned, 'no revision and no hash in the name: a new deploy would not replace it').toEqual([]);
    },
  );
});

describe('offline, after one visit', () => {
  beforeEach(() => {
    site.state.online = true; // each test starts online; the first one's visit installs the service worker
  });

  const firstVisit =
    'the first visit saves the whole build and says so, in the header above the content (bounding boxes, 1280 and ' +
    '390 px wide); Dismiss takes it away, and a second install on the device does not say it again';
  it(
    firstVisit,
    async () => {
      const page = await openPage(browser, site.url, 'index.html', { width: 1280, height: 800, timeout: WAIT_MS });
      await page.waitForFunction(
        () => document.querySelector('.offline-status')?.textContent.includes('saved on this device'),
        { timeout: WAIT_MS },
      );
      await page.waitForFunction(async () => (await navigator.serviceWorker.ready).active.state === 'activated', {
        timeout: WAIT_MS,
      });
      await page.waitForSelector('.chapter-picture');
      for (const [width, height] of [
        [1280, 800],
        [390, 844],
      ]) {
        await page.setViewport({ width, height });
        const laid = await page.evaluate(() => {
          const box = document.querySelector('.offline-status').getBoundingClientRect();
          const meets = (r) => r.left < box.right && box.left < r.right && r.top < box.bottom && box.top < r.bottom;
          const content = [document.querySelector('main'), ...document.querySelectorAll('main *')];
          const hit = document.elementFromPoint(box.left + box.width / 2, box.top + box.height / 2);
          return {
            covered: content.filter((el) => meets(el.getBoundingClientRect())).map((el) => el.className || el.tagName),
            onTop: !!hit?.closest('.offline-status'),
            inHeader: !!document.querySelector('.site-header .offline-status'),
          };
        });
        expect(laid, `${width}×${height}`).toEqual({ covered: [], onTop: true, inHeader: true });
      }
      const dismiss = await page.waitForSelector('.offline-status ::-p-text(Dismiss)');
      await dismiss.click();
      expect(await page.$('.offline-status')).toBeNull();
      expect(await page.evaluate(() => globalThis.__shadingLab.offline)).toEqual({ ready: true, announced: true });

      // the service worker gone (the browser cleared it) and installed again: the build is saved again, unsaid (and
      // this file's device has it again for the tests below)
      await page.evaluate(() =>
        navigator.serviceWorker.getRegistrations().then((rs) => Promise.all(rs.map((r) => r.unregister()))),
      );
      await page.goto('about:blank'); // no page left using it: the registration goes
      await page.goto(new URL('index.html', site.url).href, { waitUntil: 'load' });
      await page.waitForFunction(() => globalThis.__shadingLab?.offline?.ready, { timeout: WAIT_MS });
      expect(await page.evaluate(() => globalThis.__shadingLab.offline.announced)).toBe(false);
      expect(await page.$('.offline-status')).toBeNull();
      expect(page.errors).toEqual([]);
      await page.close();
    },
    TEST_BUDGET_MS,
  );

  it(`every page (${PAGES.length}) loads with no network`, async () => {
    // the first visit saved the whole build: no page needs one of its own
    // a load outlasted puppeteer's 30 s at a load average of 45
    const page = await openPage(browser, site.url, 'about:blank', { ...SMALL_VIEWPORT, timeout: WAIT_MS });
    await goOffline(page);
    for (const path of PAGES) {
      await page.goto(new URL(path === 'embed.html' ? 'embed.html?w=fresnel-curves' : path, site.url).href, {
        waitUntil: 'load',
      });
      // its code ran, from the cache (every page loads debug-hooks.js, which makes the hooks), and its first frame
      // came: a view in sight asked for a frame in the first, drew it by the second
      await page.waitForFunction(() => document.readyState === 'complete' && globalThis.__shadingLab, {
        timeout: WAIT_MS,
      });
      await afterFrames(page, 2);
      expect(await page.$eval('body', (b) => b.children.length > 0), path).toBe(true);
      expect(await page.$$eval('.widget-failure', (f) => f.map((b) => b.textContent)), path).toEqual([]);
      expect(await page.evaluate(() => !!navigator.serviceWorker.controller), path).toBe(true);
      expect(page.errors, path).toEqual([]);
      // what the page still fetches when it is left is cut off then, not counted against the next one
      await page.goto('about:blank');
      page.errors.length = 0;
    }
    site.state.online = true;
    await page.close();
  }, 300_000);

  // every chunk is in the precache manifest (checked above, in Node); the page shows that the cached ones run
  it(`widgets of each kind (${OFFLINE_WIDGETS.join(', ')}) mount with no network, from the cache`, async () => {
    const page = await visit('index.html');
    await untilLoaded(page); // what the landing page loads after its load event is not cut off by going offline
    await goOffline(page);
    const failed = [];
    for (const name of OFFLINE_WIDGETS) {
      await page.goto(new URL(`embed.html?w=${name}`, site.url).href, { waitUntil: 'load' });
      const mounted = await page
        .waitForFunction((n) => globalThis.__shadingLab?.widgets?.[n], { timeout: WAIT_MS }, name)
        .catch(() => null);
      const blocked = await page.$$eval('.blocking-message', (m) => m.map((b) => b.textContent).join(' '));
      if (!mounted || blocked) failed.push(`${name}: ${mounted ? blocked : `not mounted in ${WAIT_MS / 1000} s`}`);
      await untilLoaded(page).catch(() => failed.push(`${name}: still loading after ${WAIT_MS / 1000} s`));
      expect(page.errors, name).toEqual([]);
      // as for the pages: what is still in flight when it is left is cut off then, not counted against the next one
      await page.goto('about:blank');
      page.errors.length = 0;
    }
    expect(failed).toEqual([]);
    site.state.online = true;
    await page.close();
  }, 300_000);

  const kinds = ONE_OF_EACH_KIND.length;
  it(`every exercise (${EXERCISES.length}) is listed, one of each kind (${kinds}) opens, with no network`, async () => {
    const page = await visit('exercises.html');
    await page.waitForNetworkIdle({ idleTime: 300, timeout: WAIT_MS }); // as for the pages: nothing left in flight
    await goOffline(page);
    await page.reload({ waitUntil: 'load' });
    const listed = await page
      .waitForFunction(
        (n) => document.querySelectorAll('#exercise-list a').length === n,
        { timeout: WAIT_MS },
        EXERCISES.length,
      )
      .then(() => true)
      .catch(() => false);
    // once seen to time out (cause not found): what the page showed instead is in the message
    const shown = await page.evaluate(() => ({
      listed: document.querySelectorAll('#exercise-list a').length,
      controlled: !!navigator.serviceWorker.controller,
      messages: [...document.querySelectorAll('.blocking-message, .notice, .offline-status')].map((e) => e.textContent),
    }));
    expect(listed, `the list after an offline reload: ${JSON.stringify(shown)}, errors ${page.errors}`).toBe(true);
    const ids = await page.$$eval('#exercise-list a', (as) => as.map((a) => a.getAttribute('href').slice(1)));
    expect(ids).toEqual(expect.arrayContaining(ONE_OF_EACH_KIND));
    for (const id of ONE_OF_EACH_KIND) {
      await page.$eval(`#exercise-list a[href="#${id}"]`, (a) => a.click());
      await page.waitForFunction(
        (i) => globalThis.__shadingLab.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
        { timeout: WAIT_MS },
        id,
      );
    }
    expect(page.errors).toEqual([]);
    site.state.online = true;
    await page.close();
  }, 300_000);

  it(
    'a new deploy is fetched into the cache and announced; ' + 'after Reload the new version runs, offline too',
    async () => {
      // the deploy: a changed page, and the service worker's manifest with that page's new revision
      const marker = '<meta name="shading-lab-build" content="next" />';
      writeFileSync(
        join(dir, 'index.html'),
        readFileSync(join(dir, 'index.html'), 'utf8').replace('</head>', `${marker}</head>`),
      );
      const sw = readFileSync(join(dir, 'sw.js'), 'utf8');
      const next = sw.replace(/(url"?:\s*"index\.html",\s*"?revision"?:\s*")[0-9a-f]+"/, '$1next"');
      expect(next).not.toBe(sw);
      writeFileSync(join(dir, 'sw.js'), next);

      const page = await visit('index.html');
      expect(await page.$('meta[name="shading-lab-build"]')).toBeNull(); // the cached version still runs
      const reload = await page.waitForFunction(
        () => [...document.querySelectorAll('.offline-status button')].find((b) => b.textContent.includes('Reload')),
        { timeout: WAIT_MS },
      );
      expect(await page.$eval('.offline-status', (s) => s.textContent)).toMatch(/new version/);
      await Promise.all([page.waitForNavigation({ waitUntil: 'load' }), reload.click()]);
      expect(await page.$('meta[name="shading-lab-build"]')).not.toBeNull();
      await goOffline(page);
      await page.reload({ waitUntil: 'load' });
      expect(await page.$('meta[name="shading-lab-build"]')).not.toBeNull();
      expect(page.errors).toEqual([]);
      site.state.online = true;
      await page.close();
    },
    TEST_BUDGET_MS,
  );
});
