// What the engines runner checks in a page, the same way in every engine: the errors the page recorded (the probe
// the runner adds to its copy of the build), each canvas with a size scrolled into view and shot until it shows
// something (a blank one is one colour), and on parity.html the harness's verdict and report.
import { distinctColours } from './png.js';

/** The script the runner puts first in each page of its copy of the build: it records errors for call(). */
export const PROBE = `// Written by scripts/engines.js into its copy of the build, not part of the app: records page
// errors, unhandled rejections, resources that failed to load and console.error calls, for the runner to read.
// Left out: the ResizeObserver loop notice (raised as an error event although no script failed: the suite's
// puppeteer "pageerror" never sees it) and modulepreload links (Firefox fails those of modules already loaded; Vite's
// preload helper settles on them itself, and a chunk that does not arrive fails its import).
window.__engineErrors = [];
addEventListener('error', (e) => {
  if (/^ResizeObserver loop/.test(e.message) || e.target?.rel === 'modulepreload') return;
  const resource = e.target && e.target !== window;
  window.__engineErrors.push(resource ? 'resource failed: ' + (e.target.src || e.target.href) : 'page: ' + e.message);
}, true);
addEventListener('unhandledrejection', (e) => window.__engineErrors.push('page: ' + (e.reason?.message ?? e.reason)));
const consoleError = console.error.bind(console);
console.error = (...args) => {
  window.__engineErrors.push('console: ' + args.map(String).join(' '));
  consoleError(...args);
};
`;

const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));

/** Polls `probe` until it returns a truthy value or `timeout` ms pass; resolves to its last value. */
async function until(probe, timeout, every = 500) {
  const end = Date.now() + timeout;
  for (;;) {
    const value = await probe();
    if (value || Date.now() > end) return value;
    await sleep(every);
  }
}

function canvasesWithSize() {
  return [...document.querySelectorAll('canvas')].flatMap((c, i) => {
    const r = c.getBoundingClientRect();
    const label = c.closest('[data-widget], .widget, figure, section')?.className?.split(' ')[0] ?? c.className;
    return r.width > 0 && r.height > 0 && getComputedStyle(c).visibility !== 'hidden' ? [{ i, label }] : [];
  });
}

const emptySlots = () =>
  [...document.querySelectorAll('[data-slot]')].filter((s) => !s.childElementCount).map((s) => s.dataset.slot);

/**
 * Opens `url` and checks it: { errors, empty: [widget slots left empty], blank: [canvas labels], canvases }. A slot
 * still empty after 20 s is a widget that never mounted, with no message (a page module that failed before it).
 * A canvas counts as drawn once its shot has 3 colours or more; out of view a widget draws nothing (by design), so
 * each is scrolled to first.
 */
export async function checkPage(driver, url, { timeout = 20_000 } = {}) {
  await driver.goto(url);
  await until(() => driver.call(() => document.readyState === 'complete'), 30_000);
  await until(async () => (await driver.call(emptySlots)).length === 0, timeout);
  const empty = await driver.call(emptySlots);
  const canvases = await driver.call(canvasesWithSize);
  const blank = [];
  for (const { i, label } of canvases) {
    await driver.call((k) => document.querySelectorAll('canvas')[k].scrollIntoView({ block: 'center' }), i);
    const drawn = await until(async () => distinctColours(await driver.canvasShot(i)) >= 3, timeout, 1000);
    if (!drawn) blank.push(label || `canvas ${i}`);
  }
  const probed = await driver.call(() => window.__engineErrors ?? ['the error probe did not run']);
  return { errors: [...probed, ...driver.takeErrors()], empty, blank, canvases: canvases.length };
}

/** Runs parity.html to its verdict: { renderer, language, failed: [names], total, report } or { error }. */
export async function checkParity(driver, url, { timeout = 600_000 } = {}) {
  await driver.goto(url);
  const done = await until(
    () => driver.call(() => Boolean(document.querySelector('#parity-summary, .blocking-message'))),
    timeout,
    2000,
  );
  if (!done) return { error: `no verdict within ${timeout / 1000} s` };
  return driver.call(() => {
    const hooks = globalThis.__shadingLab ?? {};
    if (!hooks.parity) return { error: document.querySelector('.blocking-message')?.textContent ?? 'no results' };
    return {
      renderer: hooks.parityReport.renderer,
      language: navigator.language,
      total: hooks.parity.length,
      failed: hooks.parity.filter((r) => !r.pass).map((r) => `${r.name} (${r.failures}/${r.count})`),
      report: hooks.parityReport.text,
    };
  });
}
