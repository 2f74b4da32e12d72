// Helpers for the browser tests: pick lil-gui controls by label, read a widget, count WebGL draw calls.
import { expect, inject } from 'vitest';
import { SMALL_VIEWPORT, launchBrowser, openPage, settle } from './harness.js';

export const baseUrl = () => inject('baseUrl');
export { launchBrowser, settle };

/**
 * A browser test's time budget (the browser project's testTimeout in vitest.config.js), and the bound of one wait
 * for a condition inside it, below the budget so that the wait's own message comes first. Waits are for conditions,
 * never for a time (untilIdle, afterFrames, expect.poll), so these bound only what a loaded machine takes: with two
 * CPU hogs beside the suite a test took up to ~3 times as long as on an idle machine.
 */
export const TEST_BUDGET_MS = 240_000;
export const WAIT_MS = 180_000;

/** Counts every WebGL draw call of the page in window.__drawCalls. */
export function countDrawCalls() {
  window.__drawCalls = 0;
  for (const fn of [
    'drawArrays',
    'drawElements',
    'drawArraysInstanced',
    'drawElementsInstanced',
    'drawRangeElements',
  ]) {
    const orig = WebGL2RenderingContext.prototype[fn];
    WebGL2RenderingContext.prototype[fn] = function counted(...args) {
      window.__drawCalls++;
      return orig.apply(this, args);
    };
  }
}

/** Caps the samples progressive views refine to (sampleTarget in src/core/framework/debug-hooks.js). */
export function capSamples(n) {
  globalThis.__shadingLab = { ...globalThis.__shadingLab, maxSamples: n };
}

/**
 * Opens a page of the served app with its draw calls counted, at SMALL_VIEWPORT unless `width` and `height` say
 * otherwise (a test whose claim is about a size or a layout names it). `maxSamples` caps its progressive views,
 * for a test that reads a picture exact from its first samples and would otherwise wait (untilIdle) for it to
 * converge. `beforeLoad(page)` runs after those, before the navigation (openPage).
 */
export const open = (browser, path, { maxSamples, beforeLoad, ...size } = {}) =>
  openPage(browser, baseUrl(), path, {
    ...SMALL_VIEWPORT,
    ...size,
    timeout: WAIT_MS,
    beforeLoad: async (page) => {
      await page.evaluateOnNewDocument(countDrawCalls);
      if (maxSamples) await page.evaluateOnNewDocument(capSamples, maxSamples);
      await beforeLoad?.(page);
    },
  });

/** The app under a second name (localhost for 127.0.0.1): another origin, as a site embedding a widget is. */
export const otherOrigin = () => baseUrl().replace('127.0.0.1', 'localhost');

/**
 * A page standing in for another site that embeds a widget: index.html on the other origin, with the app's own
 * Content-Security-Policy bypassed there (a third-party page has its own policy, and ours allows frames from
 * the app's origin only). The embedded widget keeps its policy.
 */
export const openForeignParent = (browser) =>
  openPage(browser, baseUrl(), new URL('index.html', otherOrigin()).href, {
    ...SMALL_VIEWPORT,
    timeout: WAIT_MS,
    beforeLoad: (page) => page.setBypassCSP(true),
  });

/**
 * The frame of the iframe `selector` in `page`, once a frame shows the iframe's src (its hash aside). An iframe
 * on another site than its parent moves to a process of its own when it navigates: a wait begun on it before the move
 * (on contentFrame() of a frame just made) may never end. (A frame on its parent's site can take contentFrame().)
 */
export async function frameShowing(page, selector, { timeout = WAIT_MS } = {}) {
  const src = new URL(await (await page.waitForSelector(selector, { timeout })).evaluate((f) => f.src));
  src.hash = '';
  return page.waitForFrame((f) => !f.detached && f.url().startsWith(src.href), { timeout });
}

let steadyWaits = 0;

/**
 * Resolves once what `watch` names has held in the page (or frame) `target` for `quietChecks` checks in a row (100
 * ms apart) and at least `quietMs`: 'drawCalls', its WebGL draw count (countDrawCalls), or 'layout', its height and
 * words. Counted in the page's own checks as well as in milliseconds: a loaded machine runs the page's timers late,
 * so it waits the longer. (Checked on a timer, not per animation frame: a frame out of sight gets few frames.)
 * Rejects after `timeout`.
 */
export async function untilSteady(target, watch, { quietMs = 500, quietChecks = 5, timeout = WAIT_MS } = {}) {
  const token = ++steadyWaits; // each wait keeps its own record in the page, started afresh
  await target.waitForFunction(
    (watch, token, quietMs, quietChecks) => {
      const value =
        watch === 'drawCalls' ? window.__drawCalls : `${document.body.scrollHeight} ${document.body.innerText}`;
      const now = performance.now();
      const seen = window.__steady;
      if (seen?.token !== token || seen.value !== value) {
        window.__steady = { token, value, since: now, checks: 0 };
        return false;
      }
      seen.checks++;
      return seen.checks >= quietChecks && now - seen.since >= quietMs;
    },
    { timeout, polling: 100 },
    watch,
    token,
    quietMs,
    quietChecks,
  );
}

let idleWaits = 0;

/** Resolves once the count `key` of the test hooks (__shadingLab) of `target` is 0 for `frames` frames in a row. */
async function untilNone(target, key, frames, timeout) {
  const token = ++idleWaits; // each wait counts its own calm frames, from 0
  await target.waitForFunction(
    (token, key, frames) => {
      const calm = window.__idle?.token === token ? window.__idle.calm : 0;
      const idle = globalThis.__shadingLab?.[key] === 0;
      window.__idle = { token, calm: idle ? calm + 1 : 0 };
      return idle && calm + 1 >= frames;
    },
    { timeout, polling: 'raf' },
    token,
    key,
    frames,
  );
}

/**
 * Resolves once the page (or frame) `target` is idle for `frames` animation frames in a row: no frame a render loop
 * asked for, no timed pause of the app (the edit's pause, the figures after a drag) still to come and no chunk or
 * widget mount still loading, as the app counts them in __shadingLab.pending (src/core/framework/debug-hooks.js,
 * which makes the hooks at the page's boot: a page with no widget is idle at once). Counted in frames, not
 * milliseconds: a loaded machine only takes longer to get there. A progressive view in sight asks for frames until it
 * has its samples, so this also waits for it to converge. Rejects after `timeout` (long: the test's own time budget is
 * what bounds a wait on a loaded machine).
 */
export const untilIdle = (target, { frames = 2, timeout = 300_000 } = {}) =>
  untilNone(target, 'pending', frames, timeout);

/**
 * Resolves once the page (or frame) `target` has loaded what it shows, for `frames` animation frames in a row: no
 * chunk still being fetched and no widget still mounting (__shadingLab.loading, a mount counted until the frame after
 * its create). Not that its views are done drawing (a progressive view may go on refining): for a test whose claim is
 * a page's state, words or errors, not its pictures.
 */
export const untilLoaded = (target, { frames = 2, timeout = WAIT_MS } = {}) =>
  untilNone(target, 'loading', frames, timeout);

/** Resolves after `n` more animation frames of `target`: "nothing happens meanwhile" counted in frames, not ms. */
export const afterFrames = (target, n) =>
  target.evaluate(
    (n) =>
      new Promise((done) =>
        requestAnimationFrame(function tick() {
          --n > 0 ? requestAnimationFrame(tick) : done();
        }),
      ),
    n,
  );

/**
 * Puts the pointer at the fractions `at` = [fx, fy] of `selector`'s box until `holds()` resolves true. The box is
 * measured again at each try: on a loaded machine the layout may still be settling, and a point measured once has
 * been seen to miss the element it aimed at (in CI).
 */
export async function pointUntil(page, selector, at, holds) {
  const attempt = async () => {
    const box = await (await page.$(selector)).boundingBox();
    await page.mouse.move(box.x + box.width * at[0], box.y + box.height * at[1]);
    return holds();
  };
  await expect.poll(attempt, { timeout: WAIT_MS }).toBe(true);
}

/** Waits for a widget instance to be registered under `key` (its name, or its prefix on a page), then for idle. */
export async function widget(page, key) {
  await page.waitForFunction((k) => globalThis.__shadingLab?.widgets?.[k], { timeout: WAIT_MS }, key);
  await untilIdle(page);
}

/**
 * Waits for a widget to be registered under `key`, then for the page to have loaded (untilLoaded), not for its views
 * to be drawn: for a test that reads the page's state or words.
 */
export async function widgetLoaded(page, key) {
  await page.waitForFunction((k) => globalThis.__shadingLab?.widgets?.[k], { timeout: WAIT_MS }, key);
  await untilLoaded(page);
}

/**
 * Replaces the text of a custom term's editor (the panel of `slot`) as a user does (select all, then the new text),
 * then waits for idle: the edit's pause, the compile, the redraw and the checks after it. The text comes in one
 * input event, as a paste or a word from an input method does (Input.insertText: the browser's own text input, which
 * the editor reads from its DOM); `{ keys: true }` types it a key at a time instead (two DevTools calls a character:
 * a function of 136 characters took 4 to 11 s so at a load average of 30 to 40, against 0.1 s in one event).
 */
export async function typeCode(page, slot, text, { keys = false } = {}) {
  await page.click(`.custom-panel[data-slot="${slot}"] .cm-content`);
  await page.keyboard.down('Control');
  await page.keyboard.press('a');
  await page.keyboard.up('Control');
  await page.keyboard.press('Backspace');
  await (keys ? page.keyboard.type(text) : page.keyboard.sendCharacter(text));
  await untilIdle(page);
}

export const getState = (page, key) => page.evaluate((k) => globalThis.__shadingLab.widgets[k].getState(), key);

/** Sets a lil-gui control, found by its label, as a user would (dropdown, checkbox or number box). */
export async function setControl(page, label, value, root = 'body') {
  const ok = await page.evaluate(
    (label, value, root) => {
      const ctrl = [...document.querySelectorAll(`${root} .lil-gui .lil-controller`)].find(
        (c) => c.querySelector('.lil-name')?.textContent === label,
      );
      if (!ctrl) return false;
      const select = ctrl.querySelector('select');
      const checkbox = ctrl.querySelector('input[type=checkbox]');
      const input = ctrl.querySelector('input');
      if (select) {
        const i = [...select.options].findIndex((o) => o.textContent === value);
        if (i < 0) return false;
        select.selectedIndex = i;
        select.dispatchEvent(new Event('change'));
      } else if (checkbox) {
        checkbox.checked = value;
        checkbox.dispatchEvent(new Event('change'));
      } else {
        input.value = String(value);
        input.dispatchEvent(new Event('input'));
        input.dispatchEvent(new Event('change'));
        input.blur();
      }
      return true;
    },
    label,
    value,
    root,
  );
  if (!ok) throw new Error(`no control "${label}" with value "${value}"`);
  await untilIdle(page);
}

/** A screenshot of an element, as a base64 PNG. */
export async function shot(page, selector) {
  return (await page.$(selector)).screenshot({ encoding: 'base64' });
}

/**
 * Runs fn(imageData) in the page on a decoded base64 PNG. Sent as a string expression (DevTools evaluates it
 * outside the page's Content-Security-Policy, which forbids eval and new Function in the page's own code).
 */
export function withPixels(page, png, fn) {
  return page.evaluate(`(async () => {
    const bytes = Uint8Array.from(atob(${JSON.stringify(png)}), (ch) => ch.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
    const ctx = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    return (${fn})(ctx.getImageData(0, 0, bitmap.width, bitmap.height));
  })()`);
}

/** Distinct colours in a base64 PNG (a canvas that is not blank has many). */
export function distinctColors(page, png) {
  return withPixels(page, png, (image) => {
    const seen = new Set();
    for (let i = 0; i < image.data.length; i += 4 * 7)
      seen.add((image.data[i] << 16) | (image.data[i + 1] << 8) | image.data[i + 2]);
    return seen.size;
  });
}

/** The red channel of a base64 PNG at fractional positions [[fx, fy], ...]. */
export function redAt(page, png, points) {
  return withPixels(
    page,
    png,
    `(image) => ${JSON.stringify(points)}.map(([fx, ` +
      `fy]) => image.data[(Math.round(image.height * fy) * image.width + Math.round(image.width * fx)) * 4])`,
  );
}

/**
 * Lets `page` download into `dir`. A test file's pages live in a browser context of their own (harness.js), and
 * Chromium applies a download behaviour to the default context unless it is named.
 */
export async function allowDownloads(page, dir) {
  const cdp = await page.createCDPSession();
  const browserContextId = page.browserContext().id;
  await cdp.send('Browser.setDownloadBehavior', {
    behavior: 'allow',
    downloadPath: dir,
    ...(browserContextId ? { browserContextId } : {}),
  });
}

/**
 * The page that `click()` opens (a new tab whose address holds `fragment`), found among the context's pages by
 * polling: no target event to miss while the tab is created and then navigates.
 */
export async function pageOpenedBy(browser, click, fragment, { timeout = WAIT_MS } = {}) {
  const before = new Set(await browser.pages());
  await click();
  let opened;
  const find = async () => (opened = (await browser.pages()).find((p) => !before.has(p) && p.url().includes(fragment)));
  await expect.poll(find, { timeout, interval: 250 }).toBeTruthy();
  return /** @type {import('puppeteer-core').Page} */ (opened);
}
