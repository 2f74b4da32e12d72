// Lecturers' pages on another origin than the app: the <shading-lab-widget> element and the reveal.js plugin
// (a real deck, reveal.js from node_modules), driven from the keyboard.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { afterAll, beforeAll, describe, expect, it, onTestFinished } from 'vitest';
import { ROOT, openPage } from './harness.js';
import { longDeck, serveDecks } from './decks.js';
import { WAIT_MS, afterFrames, baseUrl, launchBrowser, untilIdle, withPixels } from './helpers.js';

/**
 * The long deck's slides, each with a widget: more than the app's budget of WebGL contexts for its frames (12) and
 * than Chromium keeps alive in a page (16, docs/embedding.md), so that a plugin which left its widgets live would
 * lose contexts before the end. One more than 16 is enough for that (each slide costs a widget's load in its frame).
 */
const LONG = 17;

let browser;
let decks;
beforeAll(async () => {
  browser = await launchBrowser();
  decks = await serveDecks({ '/long-deck.html': longDeck(LONG) });
});
afterAll(async () => {
  await browser?.close();
  decks?.close();
});

const lab = () => encodeURIComponent(new URL('embed.html', baseUrl()).href);
const WARNING = /WebGL|Too many active|context lost/i;

/** Opens a page of the lecturer's host; page.warnings keeps every WebGL warning of the page and its frames. */
async function openDeck(path, { width = 1200, height = 800 } = {}) {
  const warnings = [];
  const page = await openPage(browser, decks.url, path, {
    timeout: WAIT_MS,
    width,
    height,
    beforeLoad: (p) =>
      p.on('console', (m) => WARNING.test(m.text()) && !m.text().includes('GPU stall') && warnings.push(m.text())),
  });
  page.warnings = warnings;
  return page;
}

// The tests read a widget through its element in the lecturer's page (its state, its snapshot: both answered by
// the widget over postMessage), not by DevTools calls into the cross-origin frame: such a call waits, without a
// timeout of its own, for the frame's JavaScript context, which never comes for a frame that reveal.js has removed
// or that is still turning from the parent's blank document into the widget's process. Only the element test goes
// into its frame, once the widget has said ready there, each call bounded.
const ANSWER_MS = WAIT_MS;

/** `promise`, or a clear failure naming `what` if it does not settle within ANSWER_MS. */
function within(promise, what) {
  let timer;
  const late = new Promise((_, no) => {
    timer = setTimeout(() => no(new Error(`${what}: no answer in ${ANSWER_MS} ms`)), ANSWER_MS);
  });
  return Promise.race([promise, late]).finally(() => clearTimeout(timer));
}

/**
 * Waits until the element `selector` (default: the current slide's) has heard from its widget a state with the
 * values of `expected`; returns that whole state.
 */
async function waitForState(page, expected, selector = '.present shading-lab-widget') {
  try {
    await page.waitForFunction(
      (sel, want) => {
        const state = document.querySelector(sel)?.state;
        return state && Object.entries(want).every(([k, v]) => state[k] === v);
      },
      { timeout: WAIT_MS },
      selector,
      expected,
    );
  } catch {
    const now = await page.$eval(selector, (el) => el.state).catch(() => 'no element');
    throw new Error(`${selector} never reached ${JSON.stringify(expected)}; it has ${JSON.stringify(now)}`);
  }
  return page.$eval(selector, (el) => el.state);
}

/** The frame of the element `selector`, once its widget has said ready (the frame's document is the widget's). */
async function readyFrame(page, selector) {
  await waitForState(page, {}, selector);
  const frame = await within((await page.$(`${selector} iframe`)).contentFrame(), `the frame of ${selector}`);
  if (!frame || frame.detached) throw new Error(`the frame of ${selector} is gone`);
  return frame;
}

/** The state of the widget inside `frame`, read there (to hold the element's reports against). */
const stateInFrame = (frame) =>
  within(
    frame.evaluate(() => Object.values(globalThis.__shadingLab.widgets)[0].getState()),
    'getState in the widget frame',
  );

/** Mean |difference| per channel (0…255) of two base64 PNGs, both drawn at 64 × 64. */
const meanDifference = (page, a, b) =>
  page.evaluate(
    async (a, b) => {
      const pixels = async (b64) => {
        const img = new Image();
        img.src = `data:image/png;base64,${b64}`;
        await img.decode();
        const ctx = new OffscreenCanvas(64, 64).getContext('2d');
        ctx.drawImage(img, 0, 0, 64, 64);
        return ctx.getImageData(0, 0, 64, 64).data;
      };
      const [p, q] = [await pixels(a), await pixels(b)];
      let sum = 0;
      for (let i = 0; i < p.length; i += 4)
        sum += Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]);
      return sum / (3 * 64 * 64);
    },
    a,
    b,
  );

/** The share of a base64 PNG's pixels that differ from its top-left pixel (the background). */
const coverage = (page, png) =>
  withPixels(page, png, (image) => {
    const d = image.data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4)
      n += Math.abs(d[i] - d[0]) + Math.abs(d[i + 1] - d[1]) + Math.abs(d[i + 2] - d[2]) > 24 ? 1 : 0;
    return n / (d.length / 4);
  });

/**
 * What the browser shows of `element`, as a base64 PNG. Not captured beyond the viewport (puppeteer's default for an
 * element): to do that Chromium lays the page out at another size for a moment, which resizes the widget's frame,
 * and a resized WebGL canvas is blank until the widget's next animation frame, which may come after the capture.
 */
const onScreen = (element) => element.screenshot({ encoding: 'base64', captureBeyondViewport: false });

/** The share of the picture of the current slide's widget, by its snapshot, that is not background. */
async function snapshotCoverage(page) {
  const image = await page.$eval('.present shading-lab-widget', (el) => el.snapshot());
  return coverage(page, image.split(',')[1]);
}

/**
 * Waits until the current slide's widget shows a picture (reveal's slide transition over, the frame drawn), or
 * WAIT_MS have passed; returns the share of it that is not background.
 */
async function waitForPicture(page) {
  let share = 0;
  const picture = async () => {
    const element = await page.$('.present shading-lab-widget'); // absent for a moment while reveal swaps slides
    if (element) share = await coverage(page, await onScreen(element));
    return share;
  };
  await expect
    .poll(picture, { timeout: WAIT_MS, interval: 250 })
    .toBeGreaterThan(0.2)
    .catch(() => {});
  return share;
}

/** Where the deck is: the current slide's place and how many of its fragments are shown (reveal's classes). */
const deckPlace = (page) =>
  page.evaluate(() => {
    const slides = [...document.querySelectorAll('.reveal .slides > section')];
    const current = slides.find((s) => s.classList.contains('present'));
    return `${slides.indexOf(current)} ${current?.querySelectorAll('.fragment.visible').length}`;
  });

/** Presses `key` and waits until the deck has moved (a slide or a fragment) and the page has drawn since. */
const press = async (page, key) => {
  const was = await deckPlace(page);
  await page.keyboard.press(key);
  await expect.poll(() => deckPlace(page), { timeout: WAIT_MS, interval: 50 }).not.toBe(was);
  await afterFrames(page, 2);
};

describe('<shading-lab-widget> on another origin', () => {
  it('is one small module without three.js (gzip size printed)', () => {
    const code = readFileSync(join(ROOT, 'dist/shading-lab-widget.js'));
    const gzip = gzipSync(code, { level: 9 }).length;
    console.log(
      `dist/shading-lab-widget.js: ${code.length} B, ${gzip} B gzip; dist/shading-lab-reveal.js: ` +
        `${gzipSync(readFileSync(join(ROOT, 'dist/shading-lab-reveal.js')), { level: 9 }).length} B gzip`,
    );
    expect(gzip).toBeLessThan(10 * 1024);
    expect(code.toString()).not.toMatch(/\bimport\b|WebGLRenderer|THREE/);
  });

  it(
    'makes the iframe with this origin allowed, fires ready and change, ' +
      'exposes state, applies set() through validation',
    async () => {
      // tall enough for the whole element, which is as tall as the widget (its canvas is screenshot on screen below)
      const page = await openDeck(`/examples/element/index.html?lab=${lab()}`, { height: 1300 });
      onTestFinished(() => page.close().catch(() => {}));
      const frame = await readyFrame(page, '#zones');
      const src = await page.$eval('#zones iframe', (f) => f.src);
      expect(new URL(src).searchParams.get('origins')).toBe(decks.url);
      expect(new URL(src).searchParams.get('mode')).toBe('zones-lh');
      expect(await page.$eval('#now', (o) => o.value)).toBe('mode=zones-lh'); // the ready event's query
      expect(await page.$eval('#zones', (z) => z.state.mode)).toBe('zones-lh');

      // the page's button calls set(); the state and the widget inside the frame follow. Clicked in the page (the
      // button sits under the frame, which grows when the widget reports its height: a click at the button's
      // measured place can land on the frame)
      await page.$eval('#weighted', (button) => button.click());
      await page.waitForFunction(() => document.getElementById('now').value === 'mode=zones-lh-weighted', {
        timeout: WAIT_MS,
      });
      expect((await stateInFrame(frame)).mode).toBe('zones-lh-weighted');

      // a bad value keeps the last good one and comes back in errors; a number out of range is clamped
      const reply = await page.$eval('#zones', (z) => z.set('lightTheta=400&shape=banana'));
      expect(reply.state).toMatchObject({ lightTheta: 180, shape: 'sphere', mode: 'zones-lh-weighted' });
      expect(reply.errors.join(' ')).toMatch(/clamped to 180.*|banana/);

      // the user moves the widget: a change event with the new state
      const changed = page.evaluate(
        () =>
          new Promise((ok) =>
            document.getElementById('zones').addEventListener('change', (e) => ok(e.detail), { once: true }),
          ),
      );
      await within(
        frame.evaluate(() => Object.values(globalThis.__shadingLab.widgets)[0].update({ mode: 'zones-nv' })),
        'update in the widget frame',
      );
      expect((await changed).state.mode).toBe('zones-nv');
      expect(await page.$eval('#zones', (z) => z.query)).toContain('mode=zones-nv');

      // a snapshot is the picture the browser shows in the frame's canvas (the compositor's screenshot of it), once
      // the widget has drawn the new mode and the page has been composited since
      await untilIdle(frame, { timeout: WAIT_MS });
      await afterFrames(page, 2);
      const image = await page.$eval('#zones', (z) => z.snapshot());
      expect(image).toMatch(/^data:image\/png;base64,/);
      const shown = await onScreen(await frame.$('canvas'));
      expect(await coverage(page, shown)).toBeGreaterThan(0.2);
      expect(await meanDifference(page, image.split(',')[1], shown)).toBeLessThan(6);
      expect(page.errors).toEqual([]);
      expect(page.warnings).toEqual([]);
      await page.close();
    },
  );
});

describe('reveal.js plugin (reveal.js 6 from node_modules, the app on another origin)', () => {
  it('keyboard through slides and fragments: the widget follows its slide and fragments, back and forth', async () => {
    const page = await openDeck(`/examples/deck/index.html?lab=${lab()}`);
    await page.waitForFunction(() => document.querySelector('.reveal.ready'), { timeout: WAIT_MS });
    expect(await page.$$eval('shading-lab-widget', (els) => els.length)).toBe(1); // the next slide's, preloaded

    await press(page, 'ArrowRight');
    await waitForState(page, { mode: 'zones-nv' });
    const presenter = () =>
      page.$eval('.present shading-lab-widget iframe', (f) => new URL(f.src).searchParams.get('presenter'));
    expect(await presenter()).toBe('1'); // this slide has data-shading-lab-presenter
    await press(page, 'ArrowRight');
    await waitForState(page, { mode: 'zones-lh', lightTheta: 120, shape: 'sphere' });
    expect(await presenter()).toBeNull();
    // the slot the plugin added takes the widget's height, as far as the 700 px slide has room for it
    const slot = () =>
      page.$eval('.present [data-shading-lab-slot]', (s) => ({ height: s.offsetHeight, room: 700 - s.offsetTop }));
    await expect.poll(slot, { timeout: WAIT_MS }).toSatisfy(({ height, room }) => height === room && height > 480);
    await press(page, 'ArrowRight'); // first fragment
    await waitForState(page, { mode: 'zones-lh-weighted', shape: 'sphere' });
    await press(page, 'ArrowRight'); // second fragment
    await waitForState(page, { mode: 'zones-lh-weighted', shape: 'torusknot', lightTheta: 120 });
    await press(page, 'ArrowLeft'); // hidden again: taken back
    await waitForState(page, { mode: 'zones-lh-weighted', shape: 'sphere' });
    await press(page, 'ArrowLeft');
    await waitForState(page, { mode: 'zones-lh', shape: 'sphere' });
    await press(page, 'ArrowRight');
    await press(page, 'ArrowRight');
    await press(page, 'ArrowRight'); // the NDF slide
    expect((await waitForState(page, {})).hwhm).toBeDefined();
    await press(page, 'ArrowLeft'); // back onto the fragment slide, all its fragments shown
    await waitForState(page, { mode: 'zones-lh-weighted', shape: 'torusknot' });
    await press(page, 'ArrowLeft'); // reveal steps back through the fragments first
    await waitForState(page, { mode: 'zones-lh-weighted', shape: 'sphere' });
    await press(page, 'ArrowLeft');
    await waitForState(page, { mode: 'zones-lh', shape: 'sphere' });
    await press(page, 'ArrowLeft');
    await waitForState(page, { mode: 'zones-nv' });

    expect(await waitForPicture(page)).toBeGreaterThan(0.2);
    expect(page.errors).toEqual([]);
    expect(page.warnings).toEqual([]);
    await page.close();
  });

  it(`a ${LONG}-slide deck: at most three live widgets, each current one draws, no context lost`, async () => {
    const page = await openDeck(`/long-deck.html?lab=${lab()}`);
    onTestFinished(() => page.close().catch(() => {}));
    await page.waitForFunction(() => document.querySelector('.reveal.ready'), { timeout: WAIT_MS });
    let most = 0;
    for (let i = 0; i < LONG; i++) {
      await waitForState(page, { lightTheta: 40 + 3 * i });
      most = Math.max(most, await page.$$eval('shading-lab-widget iframe', (f) => f.length));
      // a widget whose context is lost draws nothing into its snapshot (and its frame's console says so)
      expect(await snapshotCoverage(page), `slide ${i + 1}`).toBeGreaterThan(0.2);
      if (i % 3 === 0) {
        await press(page, 'ArrowRight'); // its fragment
        await waitForState(page, { mode: 'zones-nv' });
      }
      if (i < LONG - 1) await press(page, 'ArrowRight'); // (the last slide has no next)
    }
    expect(most).toBeLessThanOrEqual(3);
    expect(await waitForPicture(page)).toBeGreaterThan(0.2);
    expect(page.errors).toEqual([]);
    expect(page.warnings).toEqual([]);
  }, 480_000); // twice TEST_BUDGET_MS: 26 key presses and 20 snapshots

  it('print view (?print-pdf): each widget is a still image in the state of its printed page', async () => {
    const page = await openDeck(`/examples/deck/index.html?print-pdf&lab=${lab()}`);
    await page.waitForSelector('.reveal[data-shading-lab-printed]', { timeout: WAIT_MS });
    expect(await page.$$eval('shading-lab-widget', (els) => els.length)).toBe(0); // no live widget left
    const stills = await page.$$eval('.pdf-page img[src^="data:image/png"]', (imgs) =>
      imgs.map((i) => ({ src: i.src, alt: i.alt })),
    );
    // slides 2 and 4, and slide 3 once per fragment step (none, one, both shown)
    expect(stills.map((s) => s.alt)).toEqual([
      'fresnel-zones: mode=zones-nv',
      'fresnel-zones: mode=zones-lh&lightTheta=120',
      'fresnel-zones: mode=zones-lh-weighted&lightTheta=120',
      'fresnel-zones: mode=zones-lh-weighted&shape=torusknot&lightTheta=120',
      'ndf-explorer: ',
    ]);
    // plots are thin lines on white
    for (const s of stills) expect(await coverage(page, s.src.split(',')[1]), s.alt).toBeGreaterThan(0.05);
    expect(new Set(stills.map((s) => s.src)).size).toBe(stills.length); // each state its own picture
    const inside = await page.$$eval('.pdf-page img', (imgs) =>
      imgs.map((img) => {
        const [r, p] = [img.getBoundingClientRect(), img.closest('.pdf-page').getBoundingClientRect()];
        return r.height > 100 && r.top >= p.top && r.bottom <= p.bottom;
      }),
    );
    expect(inside).toEqual(stills.map(() => true)); // on its printed page, not cut off below it
    const pdf = await page.pdf({ printBackground: true, preferCSSPageSize: true });
    expect(pdf.length).toBeGreaterThan(10_000);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
