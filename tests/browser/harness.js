// Shared by the browser tests and the screenshot script: find Chromium, build the app, serve it under a
// sub-path on 127.0.0.1, open pages that record every console error and page error.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { homedir, tmpdir } from 'node:os';
import { extname, join, normalize, resolve } from 'node:path';
import puppeteer from 'puppeteer-core';
import { build } from 'vite';

export const ROOT = resolve(import.meta.dirname, '../..');
export const SUB_PATH = '/course/shading-lab/'; // served under a sub-path: the build must not assume '/'
export const CHROME_HINT =
  'No Chromium found: set CHROME_PATH, or install one (Debian/Ubuntu: apt-get install -y chromium).';

export function findChrome() {
  if (process.env.CHROME_PATH && existsSync(process.env.CHROME_PATH)) return process.env.CHROME_PATH;
  for (const name of ['chromium', 'chromium-browser', 'google-chrome', 'google-chrome-stable']) {
    try {
      return execFileSync('which', [name], { encoding: 'utf8' }).trim();
    } catch {
      /* not on PATH */
    }
  }
  const cache = join(homedir(), '.cache/puppeteer/chrome');
  if (existsSync(cache)) {
    const found = execFileSync('find', [cache, '-type', 'f', '-name', 'chrome', '-perm', '-u+x'], { encoding: 'utf8' })
      .trim()
      .split('\n')[0];
    if (found) return found;
  }
  return null;
}

/**
 * Builds the app into `outDir`. BUILT_APP names a build made by this same run of the test suite (the browser tests'
 * global setup): asked for that directory again (the bench's pages and IBL parts, run by bench.test.js), it is
 * reused instead of built again, and instead of rebuilt under the server that serves it to the other tests.
 * `plugins` go beside the config's (build-cache.js: what the build read).
 */
export async function buildApp(outDir = join(ROOT, 'dist'), { plugins = [] } = {}) {
  if (process.env.BUILT_APP && resolve(process.env.BUILT_APP) === resolve(outDir)) return outDir;
  await build({ root: ROOT, logLevel: 'warn', plugins, build: { outDir, emptyOutDir: true } });
  return outDir;
}

/**
 * The browser tests' viewport where the page's size is not the claim (SwiftShader draws every pixel on the CPU):
 * helpers.js open() opens every page at it unless the test names a size. openPage's own default (1280 × 900) is
 * the scripts' and the benchmark's, whose pictures and figures are of a desktop window.
 */
export const SMALL_VIEWPORT = { width: 800, height: 600 };

const TYPES = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.css': 'text/css',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.json': 'application/json',
  '.hdr': 'application/octet-stream',
};

/** Serves `dir` at SUB_PATH; everything outside it is a 404. Resolves to { url, close }. */
export function serveStatic(dir) {
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (!path.startsWith(SUB_PATH)) return void res.writeHead(404).end();
    let file = normalize(join(dir, path.slice(SUB_PATH.length)));
    if (!file.startsWith(dir)) return void res.writeHead(403).end();
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!existsSync(file)) return void res.writeHead(404).end();
    res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
    res.end(readFileSync(file));
  });
  return new Promise((ok) => {
    server.listen(0, '127.0.0.1', () =>
      ok({ url: `http://127.0.0.1:${server.address().port}${SUB_PATH}`, close: () => server.close() }),
    );
  });
}

/** Starts a Chromium of its own (software WebGL, no network chatter); its profile folder goes when it exits. */
export async function startChromium(extraArgs = []) {
  const executablePath = findChrome();
  if (!executablePath) throw new Error(CHROME_HINT);
  const userDataDir = mkdtempSync(join(tmpdir(), 'shading-lab-chrome-'));
  const browser = await puppeteer.launch({
    executablePath,
    headless: true,
    userDataDir,
    args: [
      '--no-sandbox',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--no-first-run',
      '--enable-unsafe-swiftshader',
      '--ignore-gpu-blocklist',
      // the page's compositor in software, WebGL still on SwiftShader: four browser files 123 s → 90 s back to back
      '--disable-gpu-compositing',
      ...extraArgs,
    ],
  });
  browser.on('disconnected', () => {
    try {
      rmSync(userDataDir, { recursive: true, force: true, maxRetries: 5, retryDelay: 100 });
    } catch {
      /* Chromium may still be writing; the temp dir is left to the OS */
    }
  });
  return browser;
}

/**
 * What a test file gets from launchBrowser() in the suite: a Chromium shared by the files of its worker (kept by the
 * global setup, which starts it again if it crashed), and in it an incognito context of the file's own, so that no
 * localStorage, cache, cookie or service worker passes from one file to the next. It answers what the tests ask of
 * a browser; close() closes the file's contexts and leaves the Chromium to the next file.
 */
class FileBrowser {
  #endpoint;
  #browser = null;
  #context = null;
  #contexts = [];

  constructor(endpoint) {
    this.#endpoint = endpoint;
  }

  /** The worker's Chromium, connected again (a new one asked for) if the last one went away. */
  async #chromium() {
    if (this.#browser?.connected) return this.#browser;
    this.#context = null;
    for (let tries = 1; ; tries++) {
      const res = await fetch(this.#endpoint);
      if (!res.ok) throw new Error(`no shared Chromium: ${await res.text()}`);
      try {
        // a wait in the page (waitForFunction: a reference converging) is one DevTools call: on a loaded machine it
        // outlasts puppeteer's 180 s for a call, and the test's own time budget is what should bound it
        this.#browser = await puppeteer.connect({ browserWSEndpoint: await res.text(), protocolTimeout: 600_000 });
        return this.#browser;
      } catch (error) {
        // a Chromium that has just gone away may still be handed out, until the broker sees its connection drop
        if (tries === 5) throw error;
        await new Promise((r) => setTimeout(r, 200 * tries));
      }
    }
  }

  /** The file's context (a fresh one, should its Chromium have been replaced). */
  async #main() {
    const chromium = await this.#chromium();
    if (!this.#context || this.#context.closed) this.#context = await this.createBrowserContext(chromium);
    return this.#context;
  }

  /** Another incognito context (a second device: its own storage and service worker), closed with the file's. */
  async createBrowserContext(chromium) {
    const context = await (chromium ?? (await this.#chromium())).createBrowserContext();
    this.#contexts.push(context);
    return context;
  }

  async newPage() {
    return (await this.#main()).newPage();
  }

  async pages() {
    return (await this.#main()).pages();
  }

  async waitForTarget(predicate, options) {
    return (await this.#main()).waitForTarget(predicate, options);
  }

  async userAgent() {
    return (await this.#chromium()).userAgent();
  }

  async close() {
    await Promise.all(this.#contexts.map((c) => (c.closed ? null : c.close().catch(() => {}))));
    this.#contexts = [];
    this.#context = null;
    await this.#browser?.disconnect();
    this.#browser = null;
  }
}

/** The address of the browser tests' Chromium broker (global-setup.js) in a vitest worker; else undefined. */
async function brokerAddress() {
  if (!process.env.VITEST) return undefined;
  try {
    return (await import('vitest')).inject('chromiumBroker');
  } catch {
    return undefined; // a process a test started (the bench), which has the worker's environment but not its state
  }
}

/**
 * A browser for a test file. In the suite (the browser tests' global setup keeps one Chromium per worker), the
 * file's own incognito context in its worker's Chromium (FileBrowser); with `extraArgs` (flags of its own) or
 * `{ own: true }`, or outside the suite (the screenshot scripts), a Chromium of its own.
 */
export async function launchBrowser(extraArgs = [], { own = extraArgs.length > 0 } = {}) {
  const endpoint = own ? undefined : await brokerAddress();
  if (!endpoint) return startChromium(extraArgs);
  return new FileBrowser(`${endpoint}?worker=${process.env.VITEST_POOL_ID ?? 0}&pid=${process.pid}`);
}

/**
 * Opens `path` (relative to the served app); page.errors collects console errors and page errors.
 * `beforeLoad(page)` runs before navigation (e.g. to install instrumentation).
 */
export async function openPage(browser, baseUrl, path, { width = 1280, height = 900, beforeLoad, timeout } = {}) {
  const page = await browser.newPage();
  if (timeout) page.setDefaultTimeout(timeout); // every wait without its own bound, and the navigation
  page.errors = [];
  page.on('console', (m) => m.type() === 'error' && page.errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => page.errors.push(`page: ${e.message}`));
  page.on('requestfailed', (r) => page.errors.push(`request failed: ${r.url()}`));
  await page.setViewport({ width, height });
  await beforeLoad?.(page);
  await page.goto(new URL(path, baseUrl).href, { waitUntil: 'load' });
  return page;
}

/**
 * Two animation frames, then a fixed pause of `ms`: for the screenshot scripts and the benchmark. A test waits for
 * a condition instead (helpers.js: untilIdle, afterFrames, untilSteady), which a loaded machine cannot outrun.
 */
export async function settle(page, ms = 300) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await new Promise((r) => setTimeout(r, ms));
}
