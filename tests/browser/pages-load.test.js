// Pages load cleanly: the landing page, the Fresnel chapter and its embeds with no console error, no page error
// and no failed request; the BRDF, microfacet, NDF, visibility and performance pages with their widgets mounted
// and their views drawn; the landing page links every live page. Every built page opening under the
// Content-Security-Policy with none of these (and idle pages drawing nothing) is in csp.test.js: this file is the
// quick check of the edit loop (npm run test:quick).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { distinctColors, launchBrowser, open, settle, shot, widget } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const CANVAS = '.widget-fresnel-zones canvas';

describe('pages load cleanly', () => {
  for (const path of [
    'index.html',
    'fresnel.html',
    'embed.html?w=fresnel-curves',
    'embed.html?w=fresnel-zones',
    'embed.html?w=f0-tables',
  ]) {
    it(path, async () => {
      const page = await open(browser, path);
      if (path.includes('w=')) await widget(page, new URL(path, 'http://x').searchParams.get('w'));
      else await settle(page, 1500);
      expect(await page.$('h1, .widget')).not.toBeNull();
      if (path.includes('zones') || path === 'fresnel.html') {
        await page.$eval(CANVAS, (el) => el.scrollIntoView()); // out of view it draws nothing, by design
        await settle(page, 800);
        expect(await distinctColors(page, await shot(page, CANVAS))).toBeGreaterThan(20);
      }
      expect(page.errors).toEqual([]);
      await page.close();
    });
  }

  it('the landing page links every live page and widget', async () => {
    const page = await open(browser, 'index.html');
    await settle(page);
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

  it('an unknown widget gets a message, not a blank page', async () => {
    const page = await open(browser, 'embed.html?w=nope');
    await settle(page);
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
    ['performance.html', []],
  ]) {
    it(path, async () => {
      const page = await open(browser, path);
      for (const k of keys) await widget(page, k);
      for (const canvas of await page.$$('canvas')) {
        if (!(await canvas.boundingBox())) continue; // hidden (e.g. the second BRDF's image when there is none)
        const png = await canvas.screenshot({ encoding: 'base64' });
        expect(await distinctColors(page, png)).toBeGreaterThan(8);
      }
      expect(page.errors).toEqual([]);
      await page.close();
    });
  }
});
