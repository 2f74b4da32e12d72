// Every built page, on one visit each: it runs under the app's Content-Security-Policy with no violation, no console
// error and no page error; once every view has drawn, it draws nothing while idle; and it passes axe-core's WCAG 2.2
// A and AA rules (Deque's accessibility engine, the rules a screen-reader, voice-control or low-vision user meets:
// names, contrast, structure), with no violation allowed. Each page is opened under the policy, its widgets mounted
// and every part scrolled into sight (lazy previews load, views draw their first frame), and then axe runs over it.
// (The policy's text in every page, and that the browser enforces it, are csp.test.js.)
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, settle } from './helpers.js';
import { POLICY_PAGES, openUnderPolicy } from './under-policy.js';
import { expectIdle } from './idle.js';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'];
/**
 * The bare embed (its message), and a few widgets alone in one, beside POLICY_PAGES' fresnel-zones: the gallery's
 * previews are such embeds, so axe stays out of its frames.
 */
const EMBEDS = ['', '?w=f0-tables', '?w=brdf-lobe', '?w=material-lab&refSamples=128'].map((q) => `embed.html${q}`);
const PAGES = [...POLICY_PAGES, ...EMBEDS];

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** Scrolls through the page a screen at a time (lazy parts load, views draw their first frame), back to the top. */
async function visitAll(page) {
  const [height, screen] = await page.evaluate(() => [document.body.scrollHeight, innerHeight]);
  for (let y = screen; y < height; y += screen) {
    await page.evaluate((top) => window.scrollTo(0, top), y);
    await settle(page, 50);
  }
  await page.evaluate(() => window.scrollTo(0, 0));
  await settle(page, 300);
}

/** axe's violations in the page, one line each: rule, target selector, what to fix. */
async function violations(page) {
  await page.evaluate(AXE); // DevTools runs it outside the page's policy, which forbids inline scripts
  return page.evaluate(async (tags) => {
    const options = { runOnly: { type: 'tag', values: tags }, iframes: false };
    const result = await globalThis.axe.run(document, options);
    return result.violations.flatMap((v) =>
      v.nodes.map((n) => `${v.id} at ${n.target.join(' ')}: ${n.failureSummary.replace(/\s+/g, ' ')}`),
    );
  }, TAGS);
}

/** The wall is ready for under-policy once its first tile is up; its tiles mount one after another, all 20 here. */
const allTiles = (page) =>
  page.waitForFunction(() => Object.keys(globalThis.__shadingLab.widgets).length === 20, {
    timeout: 240_000,
    polling: 500,
  });

const tourEnd = async (page) => {
  await page.keyboard.press('End');
  await page.waitForFunction(() => {
    const tour = globalThis.__shadingLab.tour;
    return tour.ready && tour.index > 0 && !document.querySelector('.tour-end').hidden;
  });
};

// every page is checked for drawing nothing once idle but these: the gallery's and the wall's views are frames
// and tiles that context-budget.test.js follows; the embed's widget is fresnel.html's; the data: set, the exercises'
const IDLE_ELSEWHERE = /^(gallery|wall)\.html|^embed\.html|^exercises\.html\?src=/;

describe('every page under the policy, idle, and axe-core (WCAG 2.2 A and AA)', () => {
  for (const path of PAGES) {
    const idle = !IDLE_ELSEWHERE.test(path) ? '; once every view has drawn, no draw call over 2 s' : '';
    it(
      `${path.replace(/src=.*/, 'src=data:…')} runs under the policy: no violation, no console error${idle}; ` +
        'axe finds no violation',
      async () => {
        const page = await openUnderPolicy(browser, path, { width: 1280, height: 800 });
        if (path === 'wall.html') await allTiles(page);
        if (idle) await expectIdle(page); // it scrolls through the page too
        await visitAll(page);
        expect(await violations(page)).toEqual([]);
        if (path === 'tour.html') {
          await tourEnd(page);
          expect(await violations(page), 'the tour at its last step').toEqual([]);
        }
        if (path.startsWith('exercises.html?src=')) {
          expect(await page.$eval('#exercise h2', (h) => h.textContent)).toBe('A set from a data: URL');
        }
        expect(await page.evaluate(() => window.__csp ?? [])).toEqual([]);
        expect(page.errors).toEqual([]);
        await page.close();
      },
      path === 'wall.html' ? 360_000 : 240_000, // twenty widgets to mount, on software WebGL; idle pages wait inside
    );
  }
});
