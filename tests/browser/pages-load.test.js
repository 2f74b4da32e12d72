// Pages load cleanly: the landing page, the Fresnel chapter and its embeds with no console error, no page error
// and no failed request; the BRDF, microfacet, NDF, visibility and performance pages with their widgets mounted
// and their views drawn; the landing page links every live page. Every built page opening under the
// Content-Security-Policy with none of these (and idle pages drawing nothing) is in axe.test.js: this file is the
// quick check of the edit loop (npm run test:quick).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, afterFrames, distinctColors, launchBrowser, open, shot, widget } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';
import { untilCalm } from './idle.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const CANVAS = '.widget-fresnel-zones canvas';

/** Waits for the page's work to be done (its views' frames drawn, the app's pauses over): counted in frames. */
async function settled(page) {
  await afterFrames(page, 2); // a view just scrolled into sight asks for its frame by then
  await untilCalm(page);
}

describe('pages load cleanly', () => {
  for (const path of [
    'index.html',
    'fresnel.html',
    'embed.html?w=fresnel-curves',
    'embed.html?w=fresnel-zones',
    'embed.html?w=f0-tables',
  ]) {
    it(path, async () => {
      const page = await open(browser, path, SMALL_VIEWPORT);
      if (path.includes('w=')) await widget(page, new URL(path, 'http://x').searchParams.get('w'));
      else await settled(page);
      expect(await page.$('h1, .widget')).not.toBeNull();
      if (path.includes('zones') || path === 'fresnel.html') {
        await page.$eval(CANVAS, (el) => el.scrollIntoView()); // out of view it draws nothing, by design
        await settled(page);
        // polled: a view waits for what it draws with (its context, its textures) with nothing pending meanwhile
        const colors = async () => distinctColors(page, await shot(page, CANVAS));
        await expect.poll(colors, { timeout: WAIT_MS, interval: 250 }).toBeGreaterThan(20);
      }
      expect(page.errors).toEqual([]);
      await page.close();
    });
  }

  it('the landing page links every live page and widget', async () => {
    const page = await open(browser, 'index.html', SMALL_VIEWPORT);
    const links = await page.$$eval('#chapters a', (as) => as.map((a) => a.getAttribute('href')));
    expect(links).toEqual(
      expect.arrayContaining([
        'fresnel.html',
        'embed.html?w=fresnel-curves',
        'embed.html?w=fresnel-zones',
        'embed.html?w=f0-tables',
        'brdf.html',
        'microfacets.html',
        'ndf.html',
        'visibility.html',
        'embed.html?w=brdf-lobe',
        'embed.html?w=microfacets',
        'embed.html?w=energy',
        'embed.html?w=ndf-explorer',
        'embed.html?w=visibility-explorer',
      ]),
    );
    const { CHAPTERS } = await import('../../src/pages/chapters.js');
    expect(await page.$$eval('.chapter.coming', (els) => els.length)).toBe(CHAPTERS.filter((c) => !c.page).length);
    expect(await page.$$eval('.chapter.live', (els) => els.length)).toBe(CHAPTERS.filter((c) => c.page).length);
    await page.close();
  });

  const pagerTitle =
    'each chapter page ends with links to the chapters one before and one after it (as their headers number them)';
  it(pagerTitle, async () => {
    const page = await open(browser, 'index.html', SMALL_VIEWPORT);
    const files = await page.$$eval('#chapters a.chapter-title', (as) => as.map((a) => a.getAttribute('href')));
    const pages = await page.evaluate(async (list) => {
      const read = async (file) => new DOMParser().parseFromString(await (await fetch(file)).text(), 'text/html');
      return Promise.all(
        list.map(async (file) => {
          const doc = await read(file);
          const link = (rel) => doc.querySelector(`main > nav.chapter-pager:last-child a.pager-${rel}`);
          const to = (a) => a && { href: a.getAttribute('href'), text: a.textContent };
          const crumb = doc.querySelector('.site-header nav span')?.textContent;
          return { file, crumb, prev: to(link('prev')), next: to(link('next')) };
        }),
      );
    }, files);
    const byNumber = new Map(pages.map((p) => [Number.parseInt(p.crumb, 10), p]));
    expect([...byNumber.keys()]).toEqual(pages.map((_, i) => i + 1)); // the crumbs number the chapters 1, 2, …
    for (const [n, p] of byNumber) {
      for (const [rel, other, words] of [
        ['prev', byNumber.get(n - 1), '← Previous chapter'],
        ['next', byNumber.get(n + 1), 'Next chapter →'],
      ]) {
        const want = other
          ? { href: other.file, text: `${words} ${other.crumb}` }
          : { href: './', text: expect.stringMatching(/All chapters/) };
        expect(p[rel], `${p.file} ${rel}`).toMatchObject(want);
      }
    }
    await page.close();
  });

  it('an unknown widget gets a message, not a blank page', async () => {
    const page = await open(browser, 'embed.html?w=nope', SMALL_VIEWPORT);
    await page.waitForSelector('.blocking-message');
    expect(await page.$eval('.blocking-message', (el) => el.textContent)).toMatch(/no widget called/);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('chapter pages load cleanly', () => {
  for (const [path, keys] of [
    ['brdf.html', ['lobe']],
    ['microfacets.html', ['surface', 'energy']],
    ['ndf.html', ['ndf']],
    ['visibility.html', ['vis']],
    ['today.html', ['lobe']],
    ['performance.html', []],
  ]) {
    it(path, async () => {
      const page = await open(browser, path, SMALL_VIEWPORT);
      for (const k of keys) await widget(page, k);
      for (const canvas of await page.$$('canvas')) {
        if (!(await canvas.boundingBox())) continue; // hidden (e.g. the second BRDF's image when there is none)
        const colors = async () => distinctColors(page, await canvas.screenshot({ encoding: 'base64' }));
        await expect.poll(colors, { timeout: WAIT_MS, interval: 250 }).toBeGreaterThan(8);
      }
      expect(page.errors).toEqual([]);
      await page.close();
    });
  }
});
