// Lecturers' pages on another origin than the app: the <shading-lab-widget> element and the reveal.js plugin
// (a real deck, reveal.js from node_modules), driven from the keyboard.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { afterAll, beforeAll, describe, expect, it, onTestFinished } from 'vitest';
import { ROOT, openPage, settle } from './harness.js';
import { longDeck, serveDecks } from './decks.js';
import { baseUrl, launchBrowser, withPixels } from './helpers.js';

let browser;
let decks;
beforeAll(async () => {
  browser = await launchBrowser();
  decks = await serveDecks({ '/long-deck.html': longDeck(40) });
});
afterAll(async () => {
  await browser?.close();
  decks?.close();
});

const lab = () => encodeURIComponent(new URL('embed.html', baseUrl()).href);
const WARNING = /WebGL|Too many active|context lost/i;

/** Opens a page of the lecturer's host; page.warnings keeps every WebGL warning of the page and its frames. */
async function openDeck(path) {
  const warnings = [];
  const page = await openPage(browser, decks.url, path, {
    width: 1200,
    height: 800,
    beforeLoad: (p) =>
      p.on('console', (m) => WARNING.test(m.text()) && !m.text().includes('GPU stall') && warnings.push(m.text())),
  });
  page.warnings = warnings;
  return page;
}

/**
 * A DevTools call into a cross-origin frame that reveal has just removed can stay unanswered for good (seen once
 * in the full suite: the 40-slide test waited out its whole timeout); bounded here, so the caller tries again.
 */
const within = (promise, what, ms = 10_000) =>
  Promise.race([
    promise,
    new Promise((_, no) => setTimeout(() => no(new Error(`${what}: no answer in ${ms} ms`)), ms)),
  ]);

/** The frame of the element on the current slide, once its widget is up. */
async function currentFrame(page, selector = '.present shading-lab-widget') {
  const handle = await page.waitForSelector(`${selector} iframe`, { timeout: 30_000 });
  const frame = await within(handle.contentFrame(), 'contentFrame');
  await frame.waitForFunction(() => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length === 1, {
    timeout: 30_000,
  });
  return frame;
}

/** Whether the current slide's widget says its WebGL context was lost (asked again if a call goes unanswered). */
async function contextLostSaid(page) {
  for (let tries = 1; ; tries++) {
    try {
      const frame = await currentFrame(page);
      return await within(
        frame.evaluate(() => document.body.textContent.includes('context was lost')),
        'text',
      );
    } catch (e) {
      if (tries === 3) throw e;
    }
  }
}

/** The state of the widget in the iframe of `selector` (read inside the cross-origin frame). */
async function frameState(page, selector) {
  const frame = await currentFrame(page, selector);
  return within(
    frame.evaluate(() => Object.values(globalThis.__shadingLab.widgets)[0].getState()),
    'getState',
  );
}

/** Waits until the element on the current slide reports `expected` (a subset of its state) in its iframe. */
async function waitForState(page, expected) {
  const keys = Object.keys(expected);
  for (let i = 0; i < 60; i++) {
    const state = await frameState(page).catch(() => null);
    if (state && keys.every((k) => state[k] === expected[k])) return state;
    await new Promise((r) => setTimeout(r, 250));
  }
  throw new Error(
    `the widget never reached ${JSON.stringify(expected)}; it is ${JSON.stringify(await frameState(page))}`,
  );
}

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

/** Waits until the current slide's widget shows a picture (reveal's slide transition over, the frame drawn). */
async function waitForPicture(page) {
  let share = 0;
  for (let i = 0; i < 40 && share <= 0.2; i++) {
    await settle(page, 250);
    const element = await page.$('.present shading-lab-widget'); // absent for a moment while reveal swaps slides
    if (element) share = await coverage(page, await element.screenshot({ encoding: 'base64' }));
  }
  return share;
}

const press = async (page, key) => {
  await page.keyboard.press(key);
  await settle(page, 200);
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

  // retried: in two full runs (never alone) the snapshot differed from the canvas on screen (mean 61 of 255); the
  // cause is not found
  it(
    'makes the iframe with this origin allowed, fires ready and change, ' +
      'exposes state, applies set() through validation',
    { retry: 2 },
    async () => {
      const page = await openDeck(`/examples/element/index.html?lab=${lab()}`);
      onTestFinished(() => page.close().catch(() => {}));
      await page.waitForFunction(() => document.getElementById('zones').ready, { timeout: 30_000 });
      const src = await page.$eval('#zones iframe', (f) => f.src);
      expect(new URL(src).searchParams.get('origins')).toBe(decks.url);
      expect(new URL(src).searchParams.get('mode')).toBe('zones-lh');
      expect(await page.$eval('#now', (o) => o.value)).toBe('mode=zones-lh'); // the ready event's query
      expect(await page.$eval('#zones', (z) => z.state.mode)).toBe('zones-lh');

      // the page's button calls set(); the state and the widget inside the frame follow
      await page.click('#weighted');
      await page.waitForFunction(() => document.getElementById('now').value === 'mode=zones-lh-weighted', {
        timeout: 15_000,
      });
      expect((await frameState(page, '#zones')).mode).toBe('zones-lh-weighted');

      // a bad value keeps the last good one and comes back in errors; a number out of range is clamped
      const reply = await page.$eval('#zones', (z) => z.set('lightTheta=400&shape=banana'));
      expect(reply.state).toMatchObject({ lightTheta: 180, shape: 'sphere', mode: 'zones-lh-weighted' });
      expect(reply.errors.join(' ')).toMatch(/clamped to 180.*|banana/);

      // the user moves the widget: a change event with the new state
      const handle = await page.$('#zones iframe');
      const frame = await handle.contentFrame();
      const changed = page.evaluate(
        () =>
          new Promise((ok) =>
            document.getElementById('zones').addEventListener('change', (e) => ok(e.detail), { once: true }),
          ),
      );
      await frame.evaluate(() => Object.values(globalThis.__shadingLab.widgets)[0].update({ mode: 'zones-nv' }));
      expect((await changed).state.mode).toBe('zones-nv');
      expect(await page.$eval('#zones', (z) => z.query)).toContain('mode=zones-nv');

      // a snapshot is the picture the browser shows in the frame's canvas (the compositor's screenshot of it)
      await settle(page, 500);
      const image = await page.$eval('#zones', (z) => z.snapshot());
      expect(image).toMatch(/^data:image\/png;base64,/);
      const onScreen = await (await frame.$('canvas')).screenshot({ encoding: 'base64' });
      expect(await coverage(page, onScreen)).toBeGreaterThan(0.2);
      expect(await meanDifference(page, image.split(',')[1], onScreen)).toBeLessThan(6);
      expect(page.errors).toEqual([]);
      expect(page.warnings).toEqual([]);
      await page.close();
    },
  );
});

describe('reveal.js plugin (reveal.js 6 from node_modules, the app on another origin)', () => {
  it('keyboard through slides and fragments: the widget follows its slide and fragments, back and forth', async () => {
    const page = await openDeck(`/examples/deck/index.html?lab=${lab()}`);
    await page.waitForFunction(() => document.querySelector('.reveal.ready'), { timeout: 30_000 });
    expect(await page.$$eval('shading-lab-widget', (els) => els.length)).toBe(1); // the next slide's, preloaded

    await press(page, 'ArrowRight');
    await waitForState(page, { mode: 'zones-nv' });
    await press(page, 'ArrowRight');
    await waitForState(page, { mode: 'zones-lh', lightTheta: 120, shape: 'sphere' });
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
    expect((await frameState(page)).hwhm).toBeDefined();
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
  }, 180_000);

  // retried: a call into a cross-origin frame that reveal has just removed sometimes never answers (seen in a few
  // full runs, under load or beside another file); each read is bounded, but a stuck slide can use up an attempt
  const retried = { timeout: 150_000, retry: 2 };
  it('a 40-slide deck: at most three live widgets, each current one draws, no context lost', retried, async () => {
    const page = await openDeck(`/long-deck.html?lab=${lab()}`);
    onTestFinished(() => page.close().catch(() => {})); // an attempt that timed out leaves no live deck behind
    await page.waitForFunction(() => document.querySelector('.reveal.ready'), { timeout: 30_000 });
    let most = 0;
    for (let i = 0; i < 40; i++) {
      await waitForState(page, { lightTheta: 40 + 3 * i });
      most = Math.max(most, await page.$$eval('shading-lab-widget iframe', (f) => f.length));
      const lost = await contextLostSaid(page);
      expect(lost, `slide ${i + 1}`).toBe(false);
      if (i % 3 === 0) {
        await press(page, 'ArrowRight'); // its fragment
        await waitForState(page, { mode: 'zones-nv' });
      }
      await press(page, 'ArrowRight');
    }
    expect(most).toBeLessThanOrEqual(3);
    expect(await waitForPicture(page)).toBeGreaterThan(0.2);
    expect(page.errors).toEqual([]);
    expect(page.warnings).toEqual([]);
  });

  it('print view (?print-pdf): each widget is a still image in the state of its printed page', async () => {
    const page = await openDeck(`/examples/deck/index.html?print-pdf&lab=${lab()}`);
    await page.waitForSelector('.reveal[data-shading-lab-printed]', { timeout: 120_000 });
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
  }, 200_000);
});
