// Embedding, the WebGL context budget: a page of twenty 3-D widgets (wall.html) and a gallery of same-origin
// frames held within the browser's cap on live contexts, and slots given back by a removed frame. The wall, its
// twenty tiles mounted and scrolled through, and the gallery, every preview loaded, are also where they are checked
// under the policy and by axe-core (as every other page is in axe.test.js): mounting them is most of the time either
// takes. Progressive views are capped at a few samples (a picture, not a converged one, is what is checked here).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, afterFrames, baseUrl, capSamples, distinctColors, launchBrowser, open } from './helpers.js';
import { openPage } from './harness.js';
import { recordViolations } from './under-policy.js';
import { axeViolations } from './axe-run.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** Samples a progressive view (the media's path tracer, the labs' references) stops at here. */
const MAX_SAMPLES = 4;

/**
 * Counts live WebGL contexts in every frame independently of the app, as Chromium counts them: a context is
 * live from getContext until WEBGL_lose_context.loseContext() (or a loss event), and again once restored.
 * window.top.__gl: { live, most, lost, restored }.
 */
function countContexts() {
  const gl = (window.top.__gl ??= { live: 0, most: 0, lost: 0, restored: 0 }); // the top is same-origin here
  const live = new WeakSet();
  const up = (canvas, restored) => {
    if (live.has(canvas)) return;
    live.add(canvas);
    gl.live++;
    if (restored) gl.restored++;
    gl.most = Math.max(gl.most, gl.live);
  };
  const down = (canvas) => {
    if (!live.delete(canvas)) return;
    gl.live--;
    gl.lost++;
  };
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function counted(kind, ...rest) {
    const ctx = getContext.call(this, kind, ...rest);
    if (ctx && kind === 'webgl2' && !this.__counted) {
      this.__counted = true;
      this.__gl = ctx;
      this.__draws = 0; // draw calls since the context was (re)made: what is on screen was drawn by it
      up(this, false);
      this.addEventListener('webglcontextlost', () => ((this.__draws = 0), down(this)));
      this.addEventListener('webglcontextrestored', () => ((this.__draws = 0), up(this, true)));
    }
    return ctx;
  };
  for (const fn of [
    'drawArrays',
    'drawElements',
    'drawArraysInstanced',
    'drawElementsInstanced',
    'drawRangeElements',
  ]) {
    const draw = WebGL2RenderingContext.prototype[fn];
    WebGL2RenderingContext.prototype[fn] = function counted(...args) {
      this.canvas.__draws++;
      return draw.apply(this, args);
    };
  }
  const getExtension = WebGL2RenderingContext.prototype.getExtension;
  WebGL2RenderingContext.prototype.getExtension = function withLoss(name) {
    const ext = getExtension.call(this, name);
    if (ext && name === 'WEBGL_lose_context' && !ext.__counted) {
      ext.__counted = true;
      const lose = ext.loseContext.bind(ext);
      ext.loseContext = () => (down(this.canvas), lose());
    }
    return ext;
  };
}

const WEBGL_WARNING = /WebGL|Too many active/;

/**
 * Opens `path` with its WebGL contexts counted (countContexts), its WebGL console warnings kept, its policy
 * violations recorded (window.__csp) and its progressive views capped at MAX_SAMPLES, in every frame.
 */
async function openCounted(path, { beforeLoad, on = browser } = {}) {
  const warnings = [];
  const page = await openPage(on, baseUrl(), path, {
    timeout: WAIT_MS,
    beforeLoad: async (p) => {
      p.on(
        'console',
        (m) =>
          /^warn/.test(m.type()) &&
          WEBGL_WARNING.test(m.text()) &&
          !m.text().includes('GPU stall') &&
          warnings.push(m.text()),
      );
      await p.evaluateOnNewDocument(countContexts);
      await p.evaluateOnNewDocument(recordViolations);
      await p.evaluateOnNewDocument(capSamples, MAX_SAMPLES);
      await beforeLoad?.(p);
    },
  });
  page.glWarnings = warnings;
  return page;
}

/**
 * The 3-D views entirely in sight, by the index of their wall tile or gallery card (a card's view is in its
 * preview's frame, same-origin, reached from the top page): one call into the page, however many cards.
 */
const viewsInSight = (page, cardSelector) =>
  page.evaluate(
    (sel) =>
      [...document.querySelectorAll(sel)].flatMap((card, index) => {
        const frame = card.querySelector('iframe');
        const canvas = (frame ? frame.contentDocument : card)?.querySelector('.viewport > canvas');
        if (!canvas) return []; // a 2-D widget, or a preview not loaded yet
        const r = canvas.getBoundingClientRect();
        const top = r.top + (frame ? frame.getBoundingClientRect().top : 0);
        return top >= 0 && top + r.height <= innerHeight && r.height > 20 ? [index] : [];
      }),
    cardSelector,
  );

/**
 * Where the wall's scroll through stops next after `y`: where the first tile whose view has not been seen drawn
 * (`drawn`, by index) is wholly in sight, its top just below the window's (each view is shorter than the window).
 * A tile or two a stop, where 450 px steps made 53 stops: each stop is frames drawn and DevTools calls.
 */
const nextStop = (page, y, drawn) =>
  page.evaluate(
    (y, drawn) => {
      const tops = [...document.querySelectorAll('.wall-tile')]
        .map((tile, index) => [index, tile.querySelector('.viewport > canvas')])
        .filter(([index, canvas]) => canvas && !drawn.includes(index))
        .map(([, canvas]) => Math.floor(canvas.getBoundingClientRect().top + scrollY) - 8);
      const next = Math.min(...tops);
      return next > y ? next : y + 450; // none below (or one not drawn at its stop): on, as before
    },
    y,
    [...drawn],
  );

/** The canvas of the 3-D view of card `index` (viewsInSight), in its preview's frame if it has one. */
async function viewOf(page, cardSelector, index) {
  const card = (await page.$$(cardSelector))[index];
  const iframe = await card.$('iframe');
  return (iframe ? await iframe.contentFrame() : card).$('.viewport > canvas');
}

/**
 * Waits until a view's context is live and has drawn since it was (re)made, then checks that the canvas shows
 * a picture (many colours), not a blank one. (A canvas whose context is lost may still show its last picture,
 * so the picture alone proves nothing.)
 */
async function expectDrawn(page, handle, what) {
  const fresh = (c) => !c.__gl.isContextLost() && c.__draws > 0;
  // polled in the canvas's frame; a wait that runs out is reported by the expectation below, with what it found
  await handle.frame.waitForFunction(fresh, { polling: 100, timeout: 30_000 }, handle).catch(() => {});
  const why = await handle.evaluate(
    (c) =>
      `lost ${c.__gl.isContextLost()}, draws ${c.__draws}, ` +
      `message “${c.parentElement.querySelector('.blocking-message')?.textContent ?? ''}”`,
  );
  expect(await handle.evaluate(fresh), `${what}: live and drawn (${why})`).toBe(true);
  const colors = await distinctColors(page, await handle.screenshot({ encoding: 'base64' }));
  expect(colors, `${what} shows a picture`).toBeGreaterThanOrEqual(12);
}

describe('twenty 3-D widgets on one page (wall.html)', () => {
  // The wall makes and gives up dozens of WebGL contexts, in a Chromium of its own: in the same one, right after
  // the wall, a gallery preview with a live context was seen (in 2 of 5 full runs) never to draw; the cause, in the
  // app or in Chromium's GPU process, is not found yet. (The worker's shared Chromium serves the other files.)
  let own;
  beforeAll(async () => {
    own = await launchBrowser([], { own: true });
  });
  afterAll(async () => {
    await own?.close();
  });

  it(
    'draws every widget when it is in view, never holds more contexts than the budget, and loses none ' +
      'unplanned; under the policy with no violation, and axe finds no violation (WCAG 2.2 A and AA)',
    async () => {
      const page = await openCounted('wall.html', { on: own });
      // mounted one after another, on software WebGL: 201 s seen at a load average of 16. Polled from here, a short
      // call each: a waitForFunction is one DevTools call, which outlasted the own Chromium's 180 s protocol timeout
      // at a load average of 40
      const mounted = () => page.evaluate(() => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length);
      await expect.poll(mounted, { timeout: 240_000, interval: 500 }).toBe(20);
      const limit = await page.evaluate(() => window.__shadingLabGl.limit);
      expect(limit).toBeLessThan(16);
      expect(await page.$$eval('.wall-tile .viewport > canvas', (c) => c.length)).toBe(20);

      // every paused or lost message a tile shows from here to the end, whenever it comes, not only where the scroll
      // stops (the stops are few: nextStop)
      await page.$eval('#wall', (wall) => {
        const blocked = (node) =>
          (node.matches?.('.blocking-message') ? [node] : []).concat([
            ...(node.querySelectorAll?.('.blocking-message') ?? []),
          ]);
        window.__blocked = blocked(wall).map((m) => m.textContent);
        new MutationObserver((changes) => {
          for (const { addedNodes } of changes)
            for (const node of addedNodes) window.__blocked.push(...blocked(node).map((m) => m.textContent));
        }).observe(wall, { childList: true, subtree: true });
      });
      const drawn = new Set();
      const height = await page.evaluate(() => document.body.scrollHeight);
      for (let y = 0; y < height && drawn.size < 20; y = await nextStop(page, y, drawn)) {
        await page.evaluate((top) => window.scrollTo(0, top), y);
        await afterFrames(page, 2); // the views now in sight have asked for a context (expectDrawn waits for it)
        for (const index of await viewsInSight(page, '.wall-tile')) {
          if (drawn.has(index)) continue;
          await expectDrawn(page, await viewOf(page, '.wall-tile', index), `tile ${index + 1} at scroll ${y}`);
          drawn.add(index);
        }
      }
      expect([...drawn].sort((a, b) => a - b)).toEqual([...Array(20).keys()]);

      // back to the top: the first tiles gave their contexts up on the way down and draw again
      await page.evaluate(() => window.scrollTo(0, 0));
      await afterFrames(page, 2); // the views now in sight have asked for a context (expectDrawn waits for it)
      const top = await viewsInSight(page, '.wall-tile');
      expect(top.length).toBeGreaterThan(0);
      for (const index of top) {
        await expectDrawn(page, await viewOf(page, '.wall-tile', index), `tile ${index + 1} back at the top`);
      }
      expect(await page.evaluate(() => window.__blocked), 'paused or lost views, down the wall and back').toEqual([]);

      const gl = await page.evaluate(() => window.__gl);
      expect(gl.lost).toBeGreaterThan(0); // the budget really was used: contexts were given up...
      expect(gl.restored).toBeGreaterThan(0); // ...and taken back
      expect(gl.most).toBeLessThanOrEqual(limit);
      expect(await page.evaluate(() => window.__shadingLabGl.peak)).toBeLessThanOrEqual(limit);
      expect(await axeViolations(page), 'axe over the wall, its twenty tiles up').toEqual([]);
      expect(await page.evaluate(() => window.__csp ?? []), 'policy violations').toEqual([]);
      expect(page.glWarnings).toEqual([]);
      expect(page.errors).toEqual([]);
      await page.close();
    },
    420_000,
  );
});

describe('embeds in same-origin frames share one context budget', () => {
  // retried: a preview with a live context sometimes never draws (see the wall's note above; cause not found)
  const retried = { timeout: 240_000, retry: 2 };
  it(
    'a gallery with a budget of 4 draws every 3-D preview it scrolls past, with at most 4 contexts live; ' +
      'under the policy with no violation, and axe finds no violation (WCAG 2.2 A and AA)',
    retried,
    async () => {
      // Seeded in the top window before any frame loads: the frames must find and use it. Four, not three: the
      // measured-BRDF card holds two views (spheres and 3-D lobe), and with a neighbour's view above and below,
      // four can be in sight at once. The service worker is bypassed: this test is about the budget, and the
      // first visit's precaching was seen to keep a preview from drawing (open question, see the offline test).
      const LIMIT = 4;
      const page = await openCounted('gallery.html', {
        beforeLoad: async (p) => {
          await p.setBypassServiceWorker(true);
          await p.evaluateOnNewDocument((limit) => {
            if (window === window.top) window.__shadingLabGl = { limit, views: [], clock: 0, peak: 0 };
          }, LIMIT);
        },
      });
      const names = await page.$$eval('.gallery-card', (cards) => cards.map((c) => c.dataset.widget));
      const drawn = new Set();
      // the page grows as it goes: each preview takes its widget's height once that widget is up
      const height = () => page.evaluate(() => document.body.scrollHeight);
      for (let y = 0; y < (await height()); y += 400) {
        await page.evaluate((top) => window.scrollTo(0, top), y);
        await afterFrames(page, 2); // the views now in sight have asked for a context (expectDrawn waits for it)
        // every preview loaded so far has its widget up (a view not yet up is not yet in viewsInSight)
        await page.waitForFunction(
          () =>
            [...document.querySelectorAll('.gallery-card iframe')].every(
              (f) => Object.keys(f.contentWindow?.__shadingLab?.widgets ?? {}).length === 1,
            ),
          { timeout: WAIT_MS, polling: 100 },
        );
        for (const index of await viewsInSight(page, '.gallery-card')) {
          if (drawn.has(names[index])) continue;
          const canvas = await viewOf(page, '.gallery-card', index);
          await expectDrawn(page, canvas, `${names[index]} preview at scroll ${y}`);
          drawn.add(names[index]);
        }
      }
      const threeD = [
        'fresnel-zones',
        'media',
        'surfaces',
        'brdf-lobe',
        'measured-brdf',
        'ndf-explorer',
        'visibility-explorer',
        'energy',
        'diffuse-explorer',
        'material-lab',
        'lighting-models',
      ];
      expect([...drawn].sort()).toEqual([...threeD].sort());

      // back to the first 3-D preview, which gave its context up on the way down: drawn again
      await page.$eval('[data-widget="fresnel-zones"] .gallery-preview', (el) => el.scrollIntoView());
      await afterFrames(page, 2); // the views now in sight have asked for a context (expectDrawn waits for it)
      const frame = await (await page.$('[data-widget="fresnel-zones"] iframe')).contentFrame();
      await expectDrawn(page, await frame.$('.viewport > canvas'), 'fresnel-zones preview back in sight');

      const gl = await page.evaluate(() => window.__gl);
      expect(gl.lost).toBeGreaterThan(0);
      expect(gl.restored).toBeGreaterThan(0);
      expect(gl.most).toBeLessThanOrEqual(LIMIT);
      expect(await page.evaluate(() => window.__shadingLabGl.peak)).toBeLessThanOrEqual(LIMIT);
      expect(await axeViolations(page), 'axe over the gallery, every preview loaded').toEqual([]);
      expect(await page.evaluate(() => window.__csp ?? []), 'policy violations').toEqual([]);
      expect(page.glWarnings).toEqual([]);
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );

  it('a frame that is removed gives its slots back', async () => {
    const page = await open(browser, 'index.html');
    const budget = () =>
      page.evaluate(() => ({
        views: window.__shadingLabGl?.views.length,
        held: window.__shadingLabGl?.views.filter((v) => v.holds).length,
      }));
    await page.evaluate((src) => {
      document.body.replaceChildren(
        ...['a', 'b'].map((id) =>
          Object.assign(document.createElement('iframe'), { id, src, style: 'width: 900px; height: 400px' }),
        ),
      );
    }, new URL('embed.html?w=ndf-explorer', baseUrl()).href);
    for (const id of ['a', 'b']) {
      const frame = await (await page.$(`#${id}`)).contentFrame();
      await frame.waitForFunction(() => globalThis.__shadingLab?.widgets?.['ndf-explorer'], { timeout: WAIT_MS });
    }
    expect(await budget()).toEqual({ views: 2, held: 2 });
    await page.$eval('#a', (f) => f.remove());
    await page.waitForFunction(() => window.__shadingLabGl.views.length === 1, { timeout: WAIT_MS });
    expect(await budget()).toEqual({ views: 1, held: 1 });
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
