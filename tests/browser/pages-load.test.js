// Pages load cleanly: every built page opens under the Content-Security-Policy with no violation, no console
// error, no page error and no failed request; each chapter with its widgets mounted and its views drawn; once
// every view has drawn, a page issues no draw call while idle; the landing page links every live page.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { distinctColors, launchBrowser, open, settle, shot, widget } from './helpers.js';
import { POLICY_PAGES, openUnderPolicy } from './under-policy.js';
import { expectIdle } from './idle.js';

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

// every page is checked for drawing nothing once idle but these: the gallery's and the wall's views are frames
// and tiles that context-budget.test.js follows; the embed's widget is fresnel.html's; the data: set, the exercises'
const IDLE_ELSEWHERE = /^(gallery|wall)\.html|^embed\.html|^exercises\.html\?src=/;

describe('Content-Security-Policy, and idle pages draw nothing', () => {
  for (const path of POLICY_PAGES) {
    const idle = !IDLE_ELSEWHERE.test(path) ? '; once every view has drawn, no draw call over 2 s' : '';
    const name = path.replace(/src=.*/, 'src=data:…');
    it(`${name} runs under the policy: no violation, no console error${idle}`, async () => {
      const page = await openUnderPolicy(browser, path);
      if (idle) await expectIdle(page);
      expect(await page.evaluate(() => window.__csp ?? [])).toEqual([]);
      expect(page.errors).toEqual([]);
      if (path.startsWith('exercises.html?src=')) {
        expect(await page.$eval('#exercise h2', (h) => h.textContent)).toBe('A set from a data: URL');
      }
      await page.close();
    });
  }
});
