// Embedding, the gallery of embeds (gallery.html): a card and a snippet for every widget, previews loaded when
// scrolled to, a snippet that follows the preview's state and is as tall as the widget.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WIDGETS } from '../../src/widgets/registry.js';
import { WAIT_MS, baseUrl, launchBrowser, open, setControl, untilIdle } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** The src of the iframe in a card's snippet, as an HTML parser reads it. */
const snippetSrc = (page, name) =>
  page.$eval(`#${name}-snippet`, (t) =>
    new DOMParser().parseFromString(t.value, 'text/html').querySelector('iframe')?.getAttribute('src'),
  );

describe('gallery.html', () => {
  it(
    'has a card with an embed snippet for every registered widget, ' + 'and loads previews only when scrolled to',
    async () => {
      const page = await open(browser, 'gallery.html');
      await untilIdle(page);
      for (const name of Object.keys(WIDGETS)) {
        expect(await snippetSrc(page, name)).toBe(new URL(`embed.html?w=${name}`, baseUrl()).href);
        expect(await page.$eval(`[data-widget="${name}"] h2`, (h) => h.textContent)).toBe(WIDGETS[name].title);
      }
      const loaded = await page.$$eval('.gallery-preview iframe', (fs) =>
        fs.map((f) => new URL(f.src).searchParams.get('w')),
      );
      expect(loaded.length).toBeGreaterThan(0);
      expect(loaded).not.toContain('energy'); // the last card, far below
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );

  it(
    'a snippet follows the state the user leaves the preview in, is as tall as the widget measured in the preview, ' +
      'and opens in that state; Copy works from the keyboard',
    async () => {
      const page = await open(browser, 'gallery.html');
      await page.$eval('[data-widget="fresnel-zones"]', (el) => el.scrollIntoView());
      const handle = await page.waitForSelector('[data-widget="fresnel-zones"] iframe');
      const frame = await handle.contentFrame();
      await frame.waitForFunction(() => globalThis.__shadingLab?.widgets?.['fresnel-zones'], { timeout: WAIT_MS });
      await untilIdle(frame);
      await setControl(frame, 'Shape', 'Torus knot');
      await setControl(frame, 'Mode', 'Zones of l·h');
      await page.waitForFunction(
        () => document.getElementById('fresnel-zones-snippet').value.includes('mode=zones-lh'),
        {
          timeout: WAIT_MS,
        },
      );
      // the snippet's frame is as tall as the widget, measured in its preview; the preview shows it all, unscrolled
      const fits = async () => {
        const height = await page.$eval('#fresnel-zones-snippet', (t) =>
          Number(new DOMParser().parseFromString(t.value, 'text/html').querySelector('iframe').getAttribute('height')),
        );
        const inside = await frame.evaluate(() => ({
          content: Math.ceil(document.getElementById('embed').getBoundingClientRect().height),
          scroll: document.documentElement.scrollHeight - innerHeight,
        }));
        return { fits: height >= inside.content, tall: height > 700, noScroll: inside.scroll <= 0 };
      };
      await expect.poll(fits, { timeout: WAIT_MS }).toEqual({ fits: true, tall: true, noScroll: true });
      const src = await snippetSrc(page, 'fresnel-zones');
      expect(new URL(src).searchParams.get('mode')).toBe('zones-lh');
      expect(new URL(src).searchParams.get('shape')).toBe('torusknot');
      expect(new URL(src).origin).toBe(new URL(baseUrl()).origin); // absolute, from the page's location

      const copy = await page.$('[data-widget="fresnel-zones"] .gallery-copy button');
      await copy.focus();
      await page.keyboard.press('Enter');
      await page.waitForFunction(
        () => document.querySelector('[data-widget="fresnel-zones"] .gallery-status').textContent !== '',
        { timeout: WAIT_MS },
      );

      const opened = await open(browser, src);
      await opened.waitForFunction(() => globalThis.__shadingLab?.widgets?.['fresnel-zones'], { timeout: WAIT_MS });
      const state = await opened.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].getState());
      expect(state).toMatchObject({ mode: 'zones-lh', shape: 'torusknot' });
      expect(page.errors).toEqual([]);
      expect(opened.errors).toEqual([]);
      await opened.close();
      await page.close();
    },
  );

  it('its index links every registered widget card in order; Tab reaches its links and Enter jumps', async () => {
    const page = await open(browser, 'gallery.html', { height: 800 });
    const links = await page.$$eval('nav.gallery-index a', (as) =>
      as.map((a) => [a.getAttribute('href'), a.textContent, document.querySelector(a.hash)?.dataset.widget]),
    );
    expect(links).toEqual(Object.keys(WIDGETS).map((name) => [`#${name}`, WIDGETS[name].title, name]));
    const last = Object.keys(WIDGETS).at(-1);
    let focused = '';
    for (let tab = 0; tab < 60 && focused !== `#${last}`; tab++) {
      await page.keyboard.press('Tab');
      focused = await page.evaluate(
        () => document.activeElement.closest('.gallery-index') && document.activeElement.hash,
      );
    }
    expect(focused).toBe(`#${last}`);
    await page.keyboard.press('Enter');
    await page.waitForFunction((n) => location.hash === `#${n}`, {}, last);
    const top = await page.$eval(`#${last}`, (card) => card.getBoundingClientRect().top);
    expect(Math.abs(top)).toBeLessThan(20); // the card at the top of the window (scroll-margin)
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
