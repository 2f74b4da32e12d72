// Every built page, on one visit each: it runs under the app's Content-Security-Policy with no violation, no console
// error and no page error; once every view has drawn, it draws nothing while idle; and it passes axe-core's WCAG 2.2 A
// and AA rules (Deque's accessibility engine, the rules a screen-reader, voice-control or low-vision user meets: names,
// contrast, structure), with no violation allowed. Each page is opened under the policy at a small viewport
// (SwiftShader draws every pixel on the CPU; the phone's width is phone.test.js's), its progressive views capped at one
// sample, its widgets mounted and every part scrolled into sight (views draw their first frame), and back at its
// top axe runs over it, on an idle page in the frames watched for draw calls (axe reads the page and changes nothing;
// the frames are counted, so it cannot shorten them). The parity page runs four of its rows (under-policy.js; every row
// is parity.test.js's). The wall and the gallery are checked where context-budget.test.js mounts the wall's twenty
// tiles and loads every gallery preview anyway; a few widgets alone in an embed where a11y.test.js mounts each widget
// alone anyway. (The policy's text in every page, and that the browser enforces it, are csp.test.js.)
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { TEST_BUDGET_MS, launchBrowser } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';
import { POLICY_PAGES, openUnderPolicy } from './under-policy.js';
import { IDLE_FRAMES, expectIdle, visitAll } from './idle.js';
import { axeViolations } from './axe-run.js';

/**
 * Checked in context-budget.test.js, which mounts the wall's tiles and loads every gallery preview anyway; and the
 * embed with a widget (fresnel-zones, with f0-tables, brdf-lobe and material-lab: the gallery's previews are such
 * embeds, so axe stays out of its frames) in a11y.test.js, which mounts each widget alone in one anyway.
 */
const ELSEWHERE = ['wall.html', 'gallery.html', 'embed.html?w=fresnel-zones'];
/** The bare embed: its message. */
const PAGES = [...POLICY_PAGES.filter((p) => !ELSEWHERE.includes(p)), 'embed.html'];
/**
 * Samples a progressive view stops at here, its fewest (one batch or frame, sampleTarget in
 * src/core/framework/debug-hooks.js): "it stops once it has its samples" holds for any count, and axe reads the page,
 * not the picture.
 */
const MAX_SAMPLES = 1;

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const tourEnd = async (page) => {
  await page.keyboard.press('End');
  await page.waitForFunction(() => {
    const tour = globalThis.__shadingLab.tour;
    return tour.ready && tour.index > 0 && !document.querySelector('.tour-end').hidden;
  });
};

// every page is checked for drawing nothing once idle but these: the embed's widget is fresnel.html's; the data:
// set, the exercises'
const IDLE_ELSEWHERE = /^embed\.html|^exercises\.html\?src=/;

describe('every page under the policy, idle, and axe-core (WCAG 2.2 A and AA)', () => {
  for (const path of PAGES) {
    const quiet = `; once every view has drawn, no draw call over ${IDLE_FRAMES} frames`;
    const idle = !IDLE_ELSEWHERE.test(path) ? quiet : '';
    it(
      `${path.replace(/src=.*/, 'src=data:…')} runs under the policy: no violation, no console error${idle}; ` +
        'axe finds no violation',
      async () => {
        const page = await openUnderPolicy(browser, path, { ...SMALL_VIEWPORT, maxSamples: MAX_SAMPLES });
        // every part scrolled into sight, then back at the top and calm (visitAll), axe: on an idle page in the
        // frames watched for draw calls (it reads the page and changes nothing)
        const violations = idle
          ? await expectIdle(page, axeViolations)
          : await visitAll(page).then(() => axeViolations(page));
        expect(violations).toEqual([]);
        if (path === 'tour.html') {
          await tourEnd(page);
          expect(await axeViolations(page), 'the tour at its last step').toEqual([]);
        }
        if (path.startsWith('exercises.html?src=')) {
          expect(await page.$eval('#exercise h2', (h) => h.textContent)).toBe('A set from a data: URL');
        }
        expect(await page.evaluate(() => window.__csp ?? [])).toEqual([]);
        expect(page.errors).toEqual([]);
        await page.close();
      },
      TEST_BUDGET_MS, // idle pages wait inside, on software WebGL
    );
  }
});
