// The control panels in words a reader can see whole: no control's name and no menu's chosen option is cut off
// (each element's text fits its box: scroll size against client size), at 1280 px and on a 390 px phone, in the
// widgets whose menus hold the longest words. Menus are checked with their default and with their longest option.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WIDGETS } from '../../src/widgets/registry.js';
import { launchBrowser, open, widget } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** The names and the shown options of the widget's panel whose text overflows its box. */
const clipped = (page) =>
  page.$$eval('.widget-controls .lil-controller', (rows) =>
    rows
      .filter((row) => row.checkVisibility())
      .flatMap((row) => [...row.querySelectorAll(':scope > .lil-name, .lil-display')])
      .filter((el) => el.scrollWidth > el.clientWidth + 1 || el.scrollHeight > el.clientHeight + 1)
      .map((el) => el.textContent),
  );

/** Each menu's longest option but `custom` (which opens an editor, a panel of its own). */
const longestOptions = (schema) =>
  Object.fromEntries(
    Object.entries(schema)
      .filter(([, f]) => f.type === 'enum')
      .map(([key, f]) => [key, Object.entries(f.options).filter(([k]) => k !== 'custom')])
      .map(([key, options]) => [key, options.sort((a, b) => b[1].length - a[1].length)[0][0]]),
  );

describe('control panels', () => {
  for (const name of ['brdf-lobe', 'visibility-explorer', 'diffuse-explorer']) {
    it(`${name}: no control's name or chosen option is cut off at 1280 or 390 px, longest options too`, async () => {
      const page = await open(browser, `embed.html?w=${name}`, { width: 1280, height: 800 });
      await widget(page, name);
      const cut = [];
      const look = async (when) => {
        for (const [width, height] of [
          [1280, 800],
          [390, 844],
        ]) {
          await page.setViewport({ width, height });
          cut.push(...(await clipped(page)).map((text) => `${width} px, ${when}: ${text}`));
        }
      };
      await look('default');
      const { schema } = (await WIDGETS[name].load()).widget;
      await page.evaluate((n, s) => globalThis.__shadingLab.widgets[n].update(s), name, longestOptions(schema));
      await look('longest');
      expect(cut).toEqual([]);
      expect(page.errors).toEqual([]);
      await page.close();
    });
  }
});
