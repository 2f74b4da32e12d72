// The guided tour in a real Chromium: the whole tour walked by keyboard (however many steps it has), step
// URLs, history, keys that belong to a focused control, widget reuse and WebGL contexts given back.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, baseUrl, distinctColors, getState, launchBrowser, untilIdle, untilLoaded } from './helpers.js';
import { openPage, SMALL_VIEWPORT } from './harness.js';
import { tourPlan } from '../../src/tour/steps.js';
import { isWidgetName } from '../../src/widgets/registry.js';

const { steps, sections } = tourPlan(isWidgetName);

/** Records every WebGL context the page creates, with its canvas, to find the ones never given back. */
function trackContexts() {
  window.__glContexts = [];
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function tracked(type, ...rest) {
    const ctx = getContext.call(this, type, ...rest);
    if (ctx && type.startsWith('webgl') && !window.__glContexts.some((c) => c.ctx === ctx))
      window.__glContexts.push({ canvas: this, ctx });
    return ctx;
  };
}

/**
 * Progressive views (the lab's Monte Carlo reference, the media's path tracer) refine to one batch of 8 samples
 * (sampleTarget in src/core/framework/debug-hooks.js): these tests check that each step draws its picture, not that
 * it converges, and a reference left refining while the walk goes on holds up every step after it.
 */
function capSamples() {
  globalThis.__shadingLab = { maxSamples: 8 };
}

// a small window (the layout's claims have tests of their own, at 1280×800 and on a phone): software WebGL's cost
// grows with the pixels
const openTour = (browser, hash = '') =>
  openPage(browser, baseUrl(), `tour.html${hash}`, {
    ...SMALL_VIEWPORT,
    beforeLoad: (page) =>
      Promise.all([page.evaluateOnNewDocument(trackContexts), page.evaluateOnNewDocument(capSamples)]),
  });

/**
 * Waits until step `id` is shown and its widget set up (its state given: the tour's hook says ready). Whatever a
 * test then reads of the picture it polls for; a progressive view is not waited for to converge.
 */
async function onStep(page, id) {
  await page.waitForFunction(
    (id) => globalThis.__shadingLab?.tour?.ready && globalThis.__shadingLab.tour.id === id,
    { timeout: WAIT_MS }, // a widget's first set-up took 57 s (surfaces-flat) under a load average of 40
    id,
  );
}

const sameValue = (a, b) => JSON.stringify(a) === JSON.stringify(b);

/** Step k's state, walked to from step k - 1 by the keyboard (when the walk of every step has not run). */
async function walkTo(k) {
  const page = await openTour(browser, `#${steps[k - 1].id}`);
  await onStep(page, steps[k - 1].id);
  await page.keyboard.press('ArrowRight');
  await onStep(page, steps[k].id);
  const state = await getState(page, 'tour');
  expect(page.errors).toEqual([]);
  await page.close();
  return state;
}

let browser;
let first = null;
/** Each step's state as the walk found it (by step id), for the test that opens a step's URL directly. */
const walkedState = new Map();
/** The tour opened on its first step, shared by the two tests that start there and only read it before walking. */
const openFirstStep = () =>
  (first ??= openTour(browser).then(async (page) => {
    await onStep(page, steps[0].id);
    return page;
  }));
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('guided tour', () => {
  it('has one step per idea over every live chapter, and shows the chapters without steps as coming', async () => {
    expect(steps.length).toBeGreaterThanOrEqual(25);
    const page = await openFirstStep();
    const shown = await page.$$eval('.tour-sections li', (lis) =>
      lis.map((li) => ({
        key: li.dataset.section,
        coming: li.classList.contains('coming'),
        href: li.querySelector('a')?.getAttribute('href') ?? null,
      })),
    );
    expect(shown.map((s) => s.key)).toEqual(sections.map((s) => s.key));
    for (const s of sections) {
      const li = shown.find((x) => x.key === s.key);
      expect(li.coming).toBe(s.count === 0);
      if (s.count) expect(li.href).toBe(`#${steps[s.first].id}`);
    }
    expect(page.errors).toEqual([]);
  });

  it('walks from the first step to the last by keyboard, each with its widget, state, URL and picture', async () => {
    const page = await openFirstStep();
    const keys = ['ArrowRight', 'PageDown', 'Space']; // arrows, a presenter remote, the space bar
    let reused = 0;
    const took = []; // seconds per step, a figure for the log (nothing is asserted on time)
    for (let k = 0; k < steps.length; k++) {
      const step = steps[k];
      const started = Date.now();
      if (k > 0) {
        await page.evaluate(() => (document.querySelector('.tour-stage .widget').__previous = true));
        await page.keyboard.press(keys[k % keys.length]);
        await onStep(page, step.id);
      }
      const where = `step ${k + 1} (${step.id})`;
      expect(page.url(), where).toMatch(new RegExp(`tour\\.html#${step.id}$`));
      const view = await page.evaluate(() => ({
        widgets: [...document.querySelectorAll('.tour-stage .widget')].map((w) => ({
          name: w.dataset.widget,
          previous: Boolean(w.__previous),
        })),
        count: document.querySelector('.tour-count').textContent,
        title: document.querySelector('.tour-title').textContent,
        notices: document.querySelectorAll('.notice').length,
      }));
      expect(
        view.widgets.map((w) => w.name),
        where,
      ).toEqual([step.widget]);
      // the same widget going on is kept (and only updated); a different one replaces it
      if (k > 0 && steps[k - 1].widget === step.widget) {
        expect(view.widgets[0].previous, where).toBe(true);
        reused++;
      } else expect(view.widgets[0].previous, where).toBe(false);
      expect(view.count).toBe(`Step ${k + 1} of ${steps.length}`);
      expect(view.title).toBe(step.title);
      expect(view.notices, where).toBe(0);
      const state = await getState(page, 'tour');
      walkedState.set(step.id, state);
      for (const [key, value] of Object.entries(step.state))
        expect(sameValue(state[key], value), `${where}: ${key} = ${JSON.stringify(state[key])}`).toBe(true);
      // the picture: the widget's first canvas has drawn something (the F0 tables have none: their rows instead)
      const canvas = await page.$('.tour-stage .widget-view canvas');
      if (canvas) {
        await canvas.evaluate((c) => c.scrollIntoView({ block: 'center' }));
        // what is on screen, the canvas in view (captureBeyondViewport: false): puppeteer's default for a clip lays
        // the whole page out again to capture it, twice the time of the capture itself
        const picture = () =>
          canvas.screenshot({ encoding: 'base64', scrollIntoView: false, captureBeyondViewport: false });
        const colours = async () => distinctColors(page, await picture());
        await expect.poll(colours, { timeout: WAIT_MS, interval: 250, message: where }).toBeGreaterThan(8);
        await page.evaluate(() => window.scrollTo(0, 0));
      } else expect(await page.$$eval('.tour-stage tbody tr', (rows) => rows.length), where).toBeGreaterThan(5);
      expect(page.errors, where).toEqual([]);
      took.push([(Date.now() - started) / 1000, step.id]);
    }
    const slowest = took.sort((a, b) => b[0] - a[0]).slice(0, 5);
    console.log(`tour: slowest steps ${slowest.map(([t, id]) => `${id} ${t.toFixed(1)} s`).join(', ')}`);
    expect(reused).toBeGreaterThan(steps.length / 2);
    expect(await page.$eval('.tour-end', (el) => !el.hidden && el.textContent)).toMatch(/End of the tour/);
    // past the end nothing happens
    await page.keyboard.press('ArrowRight');
    await untilIdle(page);
    expect(page.url()).toMatch(new RegExp(`#${steps.at(-1).id}$`));
    // Home goes to the first step. PageUp (a remote's "back") and the browser's back button both go one step back;
    // forward returns. Walked among the first steps, which share a widget: the walk above already saw each step's
    // widget come up, and the end's (the lab, the lighting models) mounted again here took ~15 s of the file's time
    expect(steps[1].widget === steps[0].widget && steps[2].widget === steps[0].widget).toBe(true);
    await page.keyboard.press('Home');
    await onStep(page, steps[0].id);
    await page.keyboard.press('ArrowRight');
    await onStep(page, steps[1].id);
    await page.keyboard.press('ArrowRight');
    await onStep(page, steps[2].id);
    await page.keyboard.press('PageUp');
    await onStep(page, steps[1].id);
    await page.keyboard.press('PageUp');
    await onStep(page, steps[0].id);
    await page.goBack();
    await onStep(page, steps[1].id);
    await page.goForward();
    await onStep(page, steps[0].id);
    await page.keyboard.press('End');
    await onStep(page, steps.at(-1).id);
    // every widget that was replaced gave its WebGL contexts back: live contexts are the mounted widget's only
    const contexts = await page.evaluate(() => ({
      created: window.__glContexts.length,
      leaked: window.__glContexts.filter((c) => !c.canvas.isConnected && !c.ctx.isContextLost()).length,
      live: window.__glContexts.filter((c) => !c.ctx.isContextLost()).length,
      mounted: document.querySelectorAll('.tour-stage .viewport canvas').length,
    }));
    console.log(
      `tour: ${steps.length} steps walked, ${reused} reused their widget; ` +
        `WebGL contexts created ${contexts.created}, live ${contexts.live}`,
    );
    expect(contexts.created).toBeGreaterThan(contexts.mounted);
    expect(contexts.leaked).toBe(0);
    expect(contexts.live).toBe(contexts.mounted);
    expect(page.errors).toEqual([]);
    await page.close();
  }, 480_000); // 46 steps: 277 s with samples capped, 468 s without (load average 43, two cores, eight sessions)

  it('opens a step URL directly on that step, with the state it has when walked to', async () => {
    // a step that follows another of the same widget: whatever the walk left behind must not leak into it
    const k = steps.findIndex(
      (s, i) =>
        i > 0 && steps[i - 1].widget === s.widget && Object.keys(steps[i - 1].state).some((key) => !(key in s.state)),
    );
    expect(k).toBeGreaterThan(0);
    // the state the walk above found there (walked to from step k - 1 by the keyboard), else walked to here
    const walked = walkedState.get(steps[k].id) ?? (await walkTo(k));
    const direct = await openTour(browser, `#${steps[k].id}`);
    await onStep(direct, steps[k].id);
    expect(await getState(direct, 'tour')).toEqual(walked);
    expect(await direct.$eval('.tour-count', (el) => el.textContent)).toBe(`Step ${k + 1} of ${steps.length}`);
    expect(await direct.evaluate(() => document.title)).toContain(steps[k].title);
    expect(direct.errors).toEqual([]);
    await direct.close();
  });

  it('says so for an unknown step and shows the first one', async () => {
    const page = await openTour(browser, '#no-such-step');
    await onStep(page, steps[0].id);
    expect(await page.$eval('.tour-messages', (el) => el.textContent)).toMatch(/no step "no-such-step"/);
    expect(page.url()).toMatch(new RegExp(`#${steps[0].id}$`));
    // a bad hash later keeps the step that was shown
    await page.evaluate((id) => (location.hash = id), steps[2].id);
    await onStep(page, steps[2].id);
    await page.evaluate(() => (location.hash = 'banana'));
    await untilIdle(page);
    expect(page.url()).toMatch(new RegExp(`#${steps[2].id}$`));
    expect(await page.evaluate(() => globalThis.__shadingLab.tour.id)).toBe(steps[2].id);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('leaves the arrow keys to a focused slider or light, and takes them back on Escape', async () => {
    // a step of l·h zones: in the modes of n·v the light plays no part, and the view leaves its keys alone
    const id = steps.find((s) => s.widget === 'fresnel-zones' && s.state.mode?.startsWith('zones-lh')).id;
    const page = await openTour(browser, `#${id}`);
    await onStep(page, id);
    const before = await getState(page, 'tour');
    // the number box of a lil-gui slider: ↑ changes its value, ←/→ move the caret, Page keys stay with it
    const input = await page.evaluateHandle(() =>
      [...document.querySelectorAll('.tour-stage .lil-controller')]
        .find((c) => c.querySelector('.lil-name').textContent.startsWith('Light θ'))
        .querySelector('input'),
    );
    await input.focus();
    for (const key of ['ArrowRight', 'ArrowLeft', 'PageDown', 'Space', 'ArrowUp']) await page.keyboard.press(key);
    await untilIdle(page);
    expect(await page.evaluate(() => globalThis.__shadingLab.tour.id)).toBe(id);
    expect((await getState(page, 'tour')).lightTheta).not.toBe(before.lightTheta);
    // the 3-D view: its arrow keys move the light
    await page.focus('.tour-stage .viewport canvas');
    await page.keyboard.press('ArrowLeft');
    await untilIdle(page);
    expect(await page.evaluate(() => globalThis.__shadingLab.tour.id)).toBe(id);
    expect((await getState(page, 'tour')).lightPhi).not.toBe(before.lightPhi);
    // Escape gives the keys back to the tour
    await page.keyboard.press('Escape');
    await page.keyboard.press('ArrowRight');
    const next = steps[steps.findIndex((s) => s.id === id) + 1].id;
    await onStep(page, next);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('on a 390×844 touch phone: a short head, no sideways scroll, the picture in sight with its controls', async () => {
    const phone = { width: 390, height: 844, deviceScaleFactor: 1, isMobile: true, hasTouch: true };
    // two steps of one widget side by side: the second is an update, not a second mount
    const ids = ['media-straight-line', 'brdf-lobe', 'today-openpbr-layers', 'diffuse-full-moon'];
    // one page: the first step by its URL, the others by their hash, each seen from the top of the page; the
    // progressive views capped as in the walk (the claim is where things are, not what they converge to)
    const page = await openPage(browser, baseUrl(), `tour.html#${ids[0]}`, {
      beforeLoad: (p) => Promise.all([p.setViewport(phone), p.evaluateOnNewDocument(capSamples)]),
    });
    for (const id of ids) {
      await page.evaluate((id) => (window.scrollTo(0, 0), (location.hash = id)), id);
      await onStep(page, id);
      const layout = () =>
        page.evaluate(() => {
          const box = (el) => el.getBoundingClientRect().toJSON();
          const picture = document.querySelector('.tour-stage .widget-view .viewport, .tour-stage .widget-view canvas');
          const slider = document.querySelector('.tour-stage .widget-controls input');
          return {
            overflow: document.documentElement.scrollWidth - innerWidth,
            title: box(document.querySelector('.tour-title')),
            picture: box(picture),
            controls: box(document.querySelector('.tour-stage .widget-controls')),
            slider: box(slider),
            height: innerHeight,
          };
        });
      const first = await layout();
      expect(first.overflow, id).toBeLessThanOrEqual(0);
      expect(first.title.top, `${id}: the step's title starts in the top quarter`).toBeLessThan(first.height / 4);
      // scrolled to the picture, a control is on screen below it, not covering it, and can be used
      await page.evaluate(() => {
        const picture = document.querySelector('.tour-stage .widget-view .viewport, .tour-stage .widget-view canvas');
        window.scrollBy(0, picture.getBoundingClientRect().top - 8);
      });
      await untilLoaded(page);
      const seen = await layout();
      const where = `${id}: picture ${JSON.stringify(seen.picture)}, controls ${JSON.stringify(seen.controls)}`;
      expect(seen.picture.top, where).toBeGreaterThanOrEqual(0);
      expect(seen.controls.bottom, where).toBeLessThanOrEqual(seen.height + 1);
      expect(seen.controls.top, where).toBeGreaterThanOrEqual(Math.min(seen.picture.bottom, seen.height / 2) - 1);
      expect(seen.slider.bottom, where).toBeLessThanOrEqual(seen.height);
      expect(seen.slider.top, where).toBeGreaterThanOrEqual(seen.controls.top);
      expect(seen.overflow, id).toBeLessThanOrEqual(0);
      expect(page.errors, id).toEqual([]);
    }
    await page.close();
  });

  it('keeps the step’s words above the widget at 1280×800, and scrolls to the view a step speaks of', async () => {
    const step = steps.find((s) => s.look);
    expect(step, 'a step with a view to look at').toBeTruthy();
    const page = await openPage(browser, baseUrl(), `tour.html#${step.id}`, { width: 1280, height: 800 });
    await onStep(page, step.id);
    const where = await page.evaluate((look) => {
      const head = document.querySelector('.tour-head').getBoundingClientRect();
      const view = document.querySelector(`.tour-stage ${look}`).getBoundingClientRect();
      return { head: head.toJSON(), view: view.toJSON(), title: document.querySelector('.tour-title').textContent };
    }, step.look);
    expect(where.title).toBe(step.title);
    expect(where.head.top).toBeCloseTo(0, 0); // the head (buttons, title, words) stuck on top
    expect(where.view.top).toBeGreaterThanOrEqual(where.head.bottom - 1); // the view just under the words
    expect(where.view.top).toBeLessThan(where.head.bottom + 40);
    expect(where.view.bottom).toBeLessThanOrEqual(800);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('goes full screen by the button and by f, or says why not', async () => {
    const light = steps.find((s) => s.widget === 'f0-tables') ?? steps[0]; // a step without WebGL: quick in software
    const page = await openTour(browser, `#${light.id}`);
    await onStep(page, light.id);
    const status = () =>
      page.evaluate(() => ({
        full: document.fullscreenElement?.id ?? null,
        message: document.querySelector('.tour-messages').textContent,
      }));
    // full screen comes and goes asynchronously: each outcome is polled for
    const poll = (fn) => expect.poll(fn, { timeout: WAIT_MS });
    const granted = () => status().then((s) => (s.full === 'tour' ? 'granted' : s.message));
    await page.keyboard.press('f');
    await poll(async () => /^granted$|did not allow full screen/.test(await granted())).toBe(true);
    const afterKey = await status();
    if (afterKey.full) {
      expect(await page.$eval('.tour-fullscreen', (b) => b.textContent)).toBe('Exit full screen');
      await page.click('.tour-fullscreen');
      await poll(async () => (await status()).full).toBeNull();
      await page.click('.tour-fullscreen');
      await poll(async () => (await status()).full).toBe('tour');
    }
    // a refusal (here: the Fullscreen API taken away) gives a message, not an error
    if ((await status()).full) await page.click('.tour-fullscreen');
    await poll(async () => (await status()).full).toBeNull();
    await page.evaluate(
      () => void Object.defineProperty(Document.prototype, 'fullscreenEnabled', { get: () => false }),
    );
    await page.click('.tour-fullscreen');
    await poll(async () => (await status()).message).toMatch(/did not allow full screen/);
    console.log(`tour: full screen by key ${afterKey.full ? 'granted' : 'refused'} in this Chromium`);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
