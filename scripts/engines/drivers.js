// The three engines the runner drives, behind one small interface:
//   goto(url), call(fn, ...args) (fn runs in the page, its value returned; a promise is awaited),
//   canvasShot(index) → PNG bytes of the index-th <canvas>, takeErrors() → requests that failed since the last call
//   (where the protocol reports them: not WebDriver classic), close().
// Chromium (--use-angle=gl: Mesa's llvmpipe through ANGLE's GL back end) and Firefox ESR (WebDriver BiDi) through
// puppeteer-core; WebKitGTK (MiniBrowser) through WebKitWebDriver, a W3C WebDriver server spoken to over fetch.
import { spawn, execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { createServer } from 'node:net';
import puppeteer from 'puppeteer-core';
import { findChrome } from '../../tests/browser/harness.js';

export const VIEWPORT = { width: 1280, height: 800 };

const which = (...names) => {
  for (const name of names) {
    try {
      return execFileSync('which', [name], { encoding: 'utf8' }).trim();
    } catch {
      /* not on PATH */
    }
  }
  return null;
};

async function puppeteerDriver(launchOptions) {
  const browser = await puppeteer.launch({ headless: false, ...launchOptions });
  let page = null;
  const failed = [];
  return {
    async goto(url) {
      await page?.close();
      page = await browser.newPage();
      page.on('requestfailed', (r) => failed.push(`request failed: ${r.url()} (${r.failure()?.errorText})`));
      await page.setViewport(VIEWPORT);
      await page.goto(url, { waitUntil: 'load', timeout: 120_000 });
    },
    call: (fn, ...args) => page.evaluate(fn, ...args),
    canvasShot: async (index) => Buffer.from(await (await page.$$('canvas'))[index].screenshot()),
    takeErrors: () => failed.splice(0),
    close: () => browser.close(),
  };
}

export function chromiumDriver() {
  const executablePath = findChrome();
  if (!executablePath) throw new Error('no Chromium (set CHROME_PATH)');
  return puppeteerDriver({
    executablePath,
    args: ['--no-sandbox', '--use-angle=gl', '--ignore-gpu-blocklist', '--no-first-run', '--disable-sync'],
  });
}

export function firefoxDriver() {
  const executablePath = process.env.FIREFOX_PATH ?? which('firefox-esr', 'firefox');
  if (!executablePath) throw new Error('no Firefox (set FIREFOX_PATH; Debian: apt-get install firefox-esr)');
  return puppeteerDriver({ browser: 'firefox', executablePath });
}

const freePort = () =>
  new Promise((ok) => {
    const server = createServer().listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => ok(port));
    });
  });

const MINIBROWSER = ['/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser', '/usr/lib/webkit2gtk-4.1/MiniBrowser'];

/** A W3C WebDriver session on WebKitWebDriver: a command is one HTTP request, its value the JSON reply's. */
export async function webkitDriver() {
  const driverPath = process.env.WEBKIT_WEBDRIVER ?? which('WebKitWebDriver');
  const binary = process.env.WEBKIT_BROWSER ?? MINIBROWSER.find(existsSync);
  if (!driverPath || !binary) throw new Error('no WebKitWebDriver or MiniBrowser (Debian: webkit2gtk-driver)');
  const port = await freePort();
  const server = spawn(driverPath, [`--port=${port}`], { stdio: 'ignore' });
  const base = `http://127.0.0.1:${port}`;
  const send = async (method, path, body) => {
    const reply = await fetch(base + path, {
      method,
      headers: { 'content-type': 'application/json' },
      body: body && JSON.stringify(body),
    });
    const { value } = await reply.json();
    if (value?.error) throw new Error(`WebDriver ${path}: ${value.error}: ${value.message}`);
    return value;
  };
  for (let i = 0; i < 100 && !(await fetch(`${base}/status`).catch(() => null)); i++)
    await new Promise((ok) => setTimeout(ok, 100));
  const browserOptions = { binary, args: ['--automation'] };
  const { sessionId } = await send('POST', '/session', {
    capabilities: { alwaysMatch: { 'webkitgtk:browserOptions': browserOptions } },
  });
  const session = `/session/${sessionId}`;
  await send('POST', `${session}/window/rect`, VIEWPORT);
  const script = (fn) => `return (${fn}).apply(null, arguments);`;
  return {
    goto: (url) => send('POST', `${session}/url`, { url }),
    takeErrors: () => [],
    call: (fn, ...args) => send('POST', `${session}/execute/sync`, { script: script(fn), args }),
    async canvasShot(index) {
      const canvases = await send('POST', `${session}/elements`, { using: 'css selector', value: 'canvas' });
      const id = Object.values(canvases[index])[0];
      return Buffer.from(await send('GET', `${session}/element/${id}/screenshot`), 'base64');
    },
    async close() {
      await send('DELETE', session).catch(() => {});
      server.kill();
    },
  };
}

export const ENGINES = { chromium: chromiumDriver, firefox: firefoxDriver, webkit: webkitDriver };
