// Helpers for the browser tests: pick lil-gui controls by label, read a widget, count WebGL draw calls.
import { inject } from 'vitest';
import { launchBrowser, openPage, settle } from './harness.js';

export const baseUrl = () => inject('baseUrl');
export { launchBrowser, settle };

/** Counts every WebGL draw call of the page in window.__drawCalls. */
function countDrawCalls() {
  window.__drawCalls = 0;
  for (const fn of ['drawArrays', 'drawElements', 'drawArraysInstanced', 'drawElementsInstanced', 'drawRangeElements']) {
    const orig = WebGL2RenderingContext.prototype[fn];
    WebGL2RenderingContext.prototype[fn] = function counted(...args) {
      window.__drawCalls++;
      return orig.apply(this, args);
    };
  }
}

/** Opens a page of the served app with its draw calls counted. */
export const open = (browser, path, size = {}) =>
  openPage(browser, baseUrl(), path, { ...size, beforeLoad: (page) => page.evaluateOnNewDocument(countDrawCalls) });

/** Waits for a widget instance to be registered under `key` (its name, or its prefix on a page). */
export async function widget(page, key) {
  await page.waitForFunction((k) => globalThis.__shadingLab?.widgets?.[k], { timeout: 30_000 }, key);
  await settle(page, 400);
}

export const getState = (page, key) => page.evaluate((k) => globalThis.__shadingLab.widgets[k].getState(), key);

/** Sets a lil-gui control, found by its label, as a user would (dropdown, checkbox or number box). */
export async function setControl(page, label, value, root = 'body') {
  const ok = await page.evaluate(
    (label, value, root) => {
      const ctrl = [...document.querySelectorAll(`${root} .lil-gui .lil-controller`)].find((c) => c.querySelector('.lil-name')?.textContent === label);
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
  await settle(page, 400);
}

/** A screenshot of an element, as a base64 PNG. */
export async function shot(page, selector) {
  return (await page.$(selector)).screenshot({ encoding: 'base64' });
}

/** Runs fn(imageData) in the page on a decoded base64 PNG. */
export function withPixels(page, png, fn) {
  return page.evaluate(
    async (b64, body) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = new OffscreenCanvas(img.width, img.height);
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      return new Function('image', body)(ctx.getImageData(0, 0, img.width, img.height));
    },
    png,
    `return (${fn})(image);`,
  );
}

/** Distinct colours in a base64 PNG (a canvas that is not blank has many). */
export function distinctColors(page, png) {
  return withPixels(page, png, (image) => {
    const seen = new Set();
    for (let i = 0; i < image.data.length; i += 4 * 7) seen.add((image.data[i] << 16) | (image.data[i + 1] << 8) | image.data[i + 2]);
    return seen.size;
  });
}

/** The red channel of a base64 PNG at fractional positions [[fx, fy], ...]. */
export function redAt(page, png, points) {
  return withPixels(page, png, `(image) => ${JSON.stringify(points)}.map(([fx, fy]) => image.data[(Math.round(image.height * fy) * image.width + Math.round(image.width * fx)) * 4])`);
}
