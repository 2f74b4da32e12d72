// Pages on a phone: a 390 × 844 viewport with touch (isMobile, hasTouch), as an iPhone 12–15 shows them. No page is
// wider than the screen (document.documentElement.scrollWidth ≤ 390); the tour's step title is on the first
// screen; on the exercises page the question, the control that answers it and Check are on the screen together,
// none under another element (elementFromPoint at their centres); the rendering chapter's captions sit beside the
// pictures, not over them (the canvas under each caption is unpainted), and its table stays in its box. The views
// of anisotropic microfacets (issue 28) are no wider than their frame, nothing in them wider than its box unless the
// box scrolls; the material lab's captions are whole in their strips, none under its Save button.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  baseUrl,
  capSamples,
  launchBrowser,
  shot,
  untilIdle,
  untilSteady,
  widget,
  withPixels,
} from './helpers.js';
import { openPage } from './harness.js';

const PHONE = { width: 390, height: 844, isMobile: true, hasTouch: true, deviceScaleFactor: 1 };

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/**
 * Opens `path` on the phone, puppeteer's waits bounded by WAIT_MS; `maxSamples` caps its progressive views, for
 * a claim about a picture drawn, not converged.
 */
const openPhone = (path, { maxSamples } = {}) =>
  openPage(browser, baseUrl(), path, {
    ...PHONE,
    beforeLoad: async (p) => {
      await p.setViewport(PHONE);
      p.setDefaultTimeout(WAIT_MS);
      if (maxSamples) await p.evaluateOnNewDocument(capSamples, maxSamples);
    },
  });
const pageWidth = (page) => page.evaluate(() => document.documentElement.scrollWidth);

/**
 * Where each selector's element is on the screen: its box, whether the box is wholly inside the viewport, and
 * whether the element under the box's centre is that element or inside it (nothing drawn over it).
 */
const onScreen = (page, selectors) =>
  page.evaluate(
    (list) =>
      list.map((selector) => {
        const node = document.querySelector(selector);
        if (!node) return { selector, missing: true };
        const r = node.getBoundingClientRect();
        const inside = r.width > 0 && r.top >= 0 && r.left >= 0 && r.bottom <= innerHeight && r.right <= innerWidth;
        const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
        return { selector, inside, uncovered: Boolean(hit && node.contains(hit)) };
      }),
    selectors,
  );

const allVisible = (boxes) => boxes.map((b) => ({ selector: b.selector, inside: true, uncovered: true }));

/** Each widget's widths, and every element in it whose content is wider than its box when that box does not scroll. */
const overflowing = (page) =>
  page.evaluate(() => {
    const scrolls = (el) => ['auto', 'scroll'].includes(getComputedStyle(el).overflowX);
    return [...document.querySelectorAll('.widget')].map((w) => ({
      widget: w.className,
      scrollWidth: w.scrollWidth,
      clientWidth: w.clientWidth,
      wider: [w, ...w.querySelectorAll('*')]
        .filter((el) => el.scrollWidth > el.clientWidth + 1 && el.clientWidth > 0 && !scrolls(el))
        .filter((el) => !el.closest('.visually-hidden') && !el.parentElement.closest('[class*="scroll"], .formula'))
        .map((el) => `${el.tagName.toLowerCase()}.${[...el.classList].join('.')}`),
    }));
  });

describe('on a phone (390 × 844, touch)', () => {
  // the views of issue 28 (past the talk: anisotropic microfacets), each in its frame as a chapter embeds it:
  // no widget wider than the screen (scrollWidth ≤ clientWidth), nothing in it wider than its box unless that box
  // scrolls (a table, a formula)
  for (const [name, state] of [
    ['ndf-explorer', '&anisotropy=0.6'],
    ['brdf-lobe', '&anisotropy=0.6&viewPhi=40'],
    ['visibility-explorer', ''],
    ['anisotropic-microsurface', ''],
    ['material-lab', '&anisotropy=0.7&refSamples=32&area=1&ambient=1'],
  ])
    it(`${name}: no wider than the screen, nothing in it wider than its box`, async () => {
      const page = await openPhone(`embed.html?w=${name}${state}`, { maxSamples: 4 });
      await widget(page, name);
      await untilSteady(page, 'layout', { timeout: WAIT_MS });
      const [box] = await overflowing(page);
      console.log(`${name} at 390 px: scrollWidth ${box.scrollWidth}, clientWidth ${box.clientWidth}`);
      expect(box.scrollWidth).toBeLessThanOrEqual(box.clientWidth);
      expect(box.wider).toEqual([]);
      expect(await pageWidth(page)).toBeLessThanOrEqual(390);
      expect(page.errors).toEqual([]);
      await page.close();
    });

  it('the material lab: each caption whole in its strip (as tall as the longest needs), clear of Save', async () => {
    const page = await openPhone('embed.html?w=material-lab&anisotropy=0.7&refSamples=32&area=1&ambient=1', {
      maxSamples: 4,
    });
    await widget(page, 'material-lab');
    await untilSteady(page, 'layout', { timeout: WAIT_MS });
    const captions = await page.evaluate(() => {
      const save = document.querySelector('.widget-material-lab .lab-view .save-view')?.getBoundingClientRect();
      const meets = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
      return [...document.querySelectorAll('.widget-material-lab .lab-captions span')].map((span) => {
        const text = document.createRange();
        text.selectNodeContents(span);
        const lines = [...text.getClientRects()];
        return {
          text: span.textContent,
          whole: span.scrollHeight <= span.clientHeight,
          underSave: Boolean(save) && lines.some((r) => meets(r, save)),
        };
      });
    });
    expect(captions.length).toBe(3);
    expect(captions[0].text).toMatch(/punctual.*sphere light.*ambient/); // the longest: four lights
    expect(captions).toEqual(captions.map(({ text }) => ({ text, whole: true, underSave: false })));
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('performance: no wider than the screen; each table scrolls in its own box, named, reached by Tab', async () => {
    const page = await openPhone('performance.html');
    await page.waitForSelector('#latency');
    expect(await pageWidth(page)).toBeLessThanOrEqual(390);
    const tables = await page.$$eval('main table', (ts) =>
      ts.map((t) => {
        const box = t.parentElement;
        return [box.className, box.tabIndex, box.getAttribute('aria-label')?.startsWith('Table: ') ?? false];
      }),
    );
    expect(tables.length).toBeGreaterThanOrEqual(10); // a table per family, the IBL's, the latency's, the pages'
    expect(tables.filter(([c, tab, named]) => c !== 'table-scroll' || tab !== 0 || !named)).toEqual([]);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('the tour: no wider than the screen, the step’s title on the first screen', async () => {
    const page = await openPhone('tour.html');
    await page.waitForFunction(() => document.querySelector('.tour-title')?.textContent.trim());
    await untilSteady(page, 'layout', { timeout: WAIT_MS });
    expect(await pageWidth(page)).toBeLessThanOrEqual(390);
    const boxes = await onScreen(page, ['.tour-title']);
    expect(boxes).toEqual(allVisible(boxes));
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('exercises: the list is one folded line; a chosen question, its answer and Check share the screen', async () => {
    const page = await openPhone('exercises.html');
    await page.waitForSelector('#exercise-list a');
    expect(await page.$eval('#exercise-list-box', (d) => [d.open, getComputedStyle(d).position])).toEqual([
      false,
      'static',
    ]);
    // a number to type, a slider to move (a state exercise), code to write
    const cases = [
      ['water-red-depth', '#exercise-answer'],
      ['lake-mirror', '#exercise-control-theta'],
      ['shader-schlick', '.exercise-code .cm-content'],
    ];
    for (const [id, control] of cases) {
      await page.tap('#exercise-list-summary');
      await page.waitForSelector(`#exercise-list a[href="#${id}"]`, { visible: true });
      await page.tap(`#exercise-list a[href="#${id}"]`);
      await page.waitForFunction(
        (i) => globalThis.__shadingLab.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
        { timeout: WAIT_MS },
        id,
      );
      await page.waitForSelector(control);
      await untilSteady(page, 'layout', { timeout: WAIT_MS });
      expect(await page.$eval('#exercise-list-box', (d) => d.open), id).toBe(false); // folded again
      const boxes = await onScreen(page, ['.exercise-prompt', control, '.exercise-check']);
      expect(boxes, id).toEqual(allVisible(boxes));
      expect(await pageWidth(page), id).toBeLessThanOrEqual(390);
    }
    // the NDF exercise's widget holds a wide table: it scrolls in its own box
    await page.evaluate(() => (location.hash = 'which-ndf'));
    await page.waitForFunction(() => globalThis.__shadingLab.exercise?.id === 'which-ndf');
    await page.waitForSelector('.exercise-widget .data-table');
    await untilSteady(page, 'layout', { timeout: WAIT_MS });
    expect(await pageWidth(page)).toBeLessThanOrEqual(390);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('rendering: no wider than the screen; captions on unpainted canvas; the table in its box', async () => {
    // the captions' places and the canvas under them need a picture, not a converged one: 4 samples
    const page = await openPhone('rendering.html?lab.refSamples=32&models.refSamples=32', { maxSamples: 4 });
    for (const [key, section] of [
      ['lab', '#lab'],
      ['models', '#models'],
    ]) {
      await page.$eval(section, (s) => s.scrollIntoView());
      await widget(page, key);
    }
    await page.$eval('.widget-lighting-models .lab-view', (v) => v.scrollIntoView());
    await untilSteady(page, 'drawCalls', { timeout: WAIT_MS });
    expect(await pageWidth(page)).toBeLessThanOrEqual(390);

    for (const root of ['.widget-material-lab', '.widget-lighting-models']) {
      await page.$eval(`${root} .lab-view`, (v) => v.scrollIntoView());
      await untilIdle(page, { frames: 3 }); // in sight: drawn there (a frame the scroll asked for, then its samples)
      // each caption's box, in the canvas's pixels; then the canvas alone (captions hidden) read under those boxes
      const boxes = await page.$eval(`${root} .lab-view`, (view) => {
        const c = view.querySelector('canvas').getBoundingClientRect();
        return [...view.querySelectorAll('.lab-captions span')].map((s) => {
          const r = s.getBoundingClientRect();
          // 4 px in from each side: past the view's rounded corners (6 px) and the rounded edge where the strip
          // meets the picture under it
          return [r.left - c.left + 4, r.top - c.top + 4, r.width - 8, r.height - 8].map(Math.round);
        });
      });
      expect(boxes.length, root).toBeGreaterThanOrEqual(3);
      await page.addStyleTag({ content: '.lab-captions, .save-view { visibility: hidden; }' });
      const png = await shot(page, `${root} .lab-view canvas`);
      const painted = await withPixels(
        page,
        png,
        `(image) => ${JSON.stringify(boxes)}.map(([x, y, w, h]) => {
          let lit = 0;
          for (let j = Math.max(y, 0); j < Math.min(y + h, image.height); j++)
            for (let i = Math.max(x, 0); i < Math.min(x + w, image.width); i++) {
              const k = (j * image.width + i) * 4;
              if (image.data[k] + image.data[k + 1] + image.data[k + 2] > 30) lit++;
            }
          return lit;
        })`,
      );
      expect(Object.values(painted), root).toEqual(boxes.map(() => 0));
      await page.addStyleTag({ content: '.lab-captions, .save-view { visibility: visible; }' });
    }

    // the lighting models' table: inside its widget, and "where it fails" in lines of several words
    // (one evaluate: the widget writes its table anew with each frame it draws)
    const table = await page.evaluate(() => {
      const t = document.querySelector('.models-table');
      const box = t.closest('.widget').getBoundingClientRect();
      const fails = [...t.querySelectorAll('tbody td:last-child')].map((td) => td.getBoundingClientRect().width);
      return { right: t.getBoundingClientRect().right, boxRight: box.right, narrowest: Math.min(...fails) };
    });
    expect(table.right).toBeLessThanOrEqual(table.boxRight + 0.5);
    expect(table.narrowest).toBeGreaterThan(250);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
