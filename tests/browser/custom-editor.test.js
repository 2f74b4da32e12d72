// User-written terms in brdf-lobe (issue 13), in a real Chromium: code typed into the editor as a user types it,
// for each slot the widget offers, drawn as the term predicts (the truth: the JS reference terms of src/math, and
// the polar plot's geometry); compile errors on the user's line with the last picture kept; the loop check; the
// URL and postMessage carrying the code; code from a link waiting for a click; a lost context and its recovery.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  baseUrl,
  getState,
  launchBrowser,
  open,
  shot,
  typeCode,
  untilIdle,
  widget,
  widgetLoaded,
  withPixels,
} from './helpers.js';
import { defaultState } from '../../src/core/framework/state.js';
import { schema } from '../../src/widgets/brdf-lobe/schema.js';
import { lobePeak, lobeScene } from '../../src/widgets/brdf-lobe/model.js';

// each test types code that is compiled in software WebGL, some twice: one took over 60 s under a load average of 44

let browser;
/** @type {Promise<import('puppeteer-core').Page> | undefined} */
let shared;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await (await shared)?.close();
  await browser?.close();
});

const KEY = 'brdf-lobe';
/** B is GGX with height-correlated Smith at A's α: the catalogue's own lobe beside the user's. */
const WITH_B = 'compare=1&D2=ggx&V2=smithGGXCorrelated&alpha2=0.3';
const JS_STATE = { ...defaultState(schema), compare: true, D2: 'ggx', V2: 'smithGGXCorrelated', alpha2: 0.3 };
/** The peak of lobe A of the JS reference (catalogue terms in float64) for a state. */
const jsPeak = (partial) => lobePeak(lobeScene({ ...JS_STATE, ...partial }).lobeA)[1];

/** A kept page, made the shown tab: a tab behind another gets no animation frames, and the waits count frames. */
async function inFront(opened) {
  const page = await opened;
  await page.bringToFront();
  return page;
}

const unique = () => `// ${Math.random().toString(36).slice(2)}\n`;
const D_TWICE_GGX = `float customD(float nh, float alpha) {
float a2 = alpha * alpha;
float d = nh * nh * (a2 - 1.0) + 1.0;
return 2.0 * a2 / (PI * d * d);
}`;

/**
 * The widget alone, in a window just wider than where its row of views folds to one column (900 px, styles.css).
 * `{ drawn: false }`, for a page whose state is read and not its pictures: waits for it to have loaded, not to idle.
 */
async function openLobe(query, { drawn = true } = {}) {
  const page = await open(browser, `embed.html?w=${KEY}&${query}`, { width: 960, height: 1400 });
  if (!drawn) {
    await widgetLoaded(page, KEY);
    return page;
  }
  await widget(page, KEY);
  await page.waitForSelector('.custom-panel .cm-content', { timeout: WAIT_MS });
  await untilIdle(page);
  return page;
}

/**
 * One page of the widget with the user's D beside B, for the cases that only type into it (each page load compiles
 * the widget's programs again). Opened by the first case that asks, so that each still runs alone (-t): the first
 * reads the starter before it types; the others read the code they type, or only that their code changed nothing.
 */
const sharedLobe = () => inFront((shared ??= openLobe(`D=custom&${WITH_B}`)));
/** A second page, for the cases that type V and F, then the whole BRDF (set by update: no page load between). */
let termsPage;
const termsLobe = () => inFront((termsPage ??= openLobe(`V=custom&F=custom&${WITH_B}`)));
afterAll(async () => (await termsPage)?.close());

/** The polar plot's words: each lobe's peak, e.g. { A: 0.95, B: 0.47 } (in 1/sr). */
async function polarPeaks(page) {
  const label = await page.$eval('.polar-plot canvas', (c) => c.getAttribute('aria-label'));
  return Object.fromEntries(
    [...label.matchAll(/([AB]) peaks at [-\d.]+° \(([\d.e+-]+) \/sr\)/g)].map((m) => [m[1], +m[2]]),
  );
}

/**
 * The farthest pixel of each lobe's stroke from the dial's centre (polar-plot.js: centre at (w/2, 0.92 h)), in
 * pixels: A orange (#d55e00), B green (#009e73).
 */
function lobeRadii(page, png) {
  return withPixels(
    page,
    png,
    `(image) => {
      const [cx, cy] = [image.width / 2, image.height * 0.92];
      const near = (i, c) =>
        Math.abs(image.data[i] - c[0]) + Math.abs(image.data[i + 1] - c[1]) + Math.abs(image.data[i + 2] - c[2]) < 40;
      const r = { A: 0, B: 0 };
      for (let y = 0; y < image.height; y++)
        for (let x = 0; x < image.width; x++) {
          const i = (y * image.width + x) * 4;
          const d = Math.hypot(x - cx, y - cy);
          if (near(i, [213, 94, 0])) r.A = Math.max(r.A, d);
          if (near(i, [0, 158, 115])) r.B = Math.max(r.B, d);
        }
      return r;
    }`,
  );
}

const panelText = (page, slot, selector) =>
  page.$eval(`.custom-panel[data-slot="${slot}"] ${selector}`, (el) => el.textContent);

describe('custom terms in brdf-lobe: typed code draws as the term predicts', () => {
  it('D: 2 × GGX typed in doubles the lobe beside GGX (B): radii 2 : 1 on the dial, peak 2 × the JS GGX', async () => {
    const page = await sharedLobe();
    const start = await polarPeaks(page);
    expect(start.A / jsPeak({})).toBeCloseTo(1, 2); // the starter is GGX
    await typeCode(page, 'D', D_TWICE_GGX, { keys: true }); // a key at a time, as a user types
    expect((await getState(page, KEY)).codeD).toMatch(/return 2\.0 \* a2/);
    const peaks = await polarPeaks(page);
    expect(peaks.A / (2 * jsPeak({}))).toBeCloseTo(1, 2);
    expect(peaks.B / jsPeak({})).toBeCloseTo(1, 2);
    const radii = await lobeRadii(page, await shot(page, '.polar-plot canvas'));
    expect(radii.A / radii.B).toBeGreaterThan(1.94);
    expect(radii.A / radii.B).toBeLessThan(2.06);
    expect(await panelText(page, 'D', '.custom-status')).toMatch(/Running your code/);
    expect(page.errors).toEqual([]);
  });

  it('V: ½ × height-correlated Smith and F: 2 F0 give the JS reference lobe × ½ × 2 F0 (F = 1)', async () => {
    const page = await termsLobe();
    await typeCode(
      page,
      'V',
      `float customV(float nl, float nv, float alpha) {
float a2 = alpha * alpha;
return 1.0 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
}`,
    );
    await typeCode(page, 'F', 'vec3 customF(vec3 f0, float lh) {\nreturn 2.0 * f0;\n}');
    const peaks = await polarPeaks(page);
    // the JS reference: V halved, and F = 2 F0 is the catalogue's F = 1 times 2 F0
    const expected = 0.5 * 2 * JS_STATE.f0 * jsPeak({ F: 'one' });
    expect(peaks.A / expected).toBeCloseTo(1, 2);
    expect(page.errors).toEqual([]);
  });

  it('whole BRDF: a Lambertian 0.5/π draws a half-disc of radius 0.5/π (every direction alike)', async () => {
    // the V and F case's page, set to what a page opened with brdf=custom alone shows
    const page = await termsLobe();
    await page.evaluate((s) => globalThis.__shadingLab.widgets['brdf-lobe'].update(s), {
      ...defaultState(schema),
      brdf: 'custom',
    });
    await untilIdle(page);
    await typeCode(page, 'brdf', 'vec3 customBRDF(vec3 l, vec3 v) {\nreturn vec3(0.5 / PI);\n}');
    expect((await polarPeaks(page)).A).toBeCloseTo(0.5 / Math.PI, 3);
    const png = await shot(page, '.polar-plot canvas');
    // on a constant lobe, the stroke is as far from the centre at −20° as at −75° (where no arrow is drawn)
    const radiusAt = (deg) =>
      withPixels(
        page,
        png,
        `(image) => {
          const [cx, cy] = [image.width / 2, image.height * 0.92];
          const [sx, sy] = [Math.sin(${deg} * Math.PI / 180), -Math.cos(${deg} * Math.PI / 180)];
          let far = 0;
          for (let r = 0; r < image.height; r += 0.5) {
            const i = (Math.round(cy + r * sy) * image.width + Math.round(cx + r * sx)) * 4;
            if (Math.abs(image.data[i] - 213) + Math.abs(image.data[i + 1] - 94) + image.data[i + 2] < 60) far = r;
          }
          return far;
        }`,
      );
    const [r20, r75] = [await radiusAt(-20), await radiusAt(-75)];
    expect(r20).toBeGreaterThan(50);
    expect(Math.abs(r20 - r75)).toBeLessThan(3);
    expect(page.errors).toEqual([]);
  });
});

describe('custom terms in brdf-lobe: errors, safety, sharing', () => {
  it('a compile error lands on the user’s line, and the last picture stays', async () => {
    const page = await sharedLobe();
    await typeCode(page, 'D', D_TWICE_GGX);
    const good = await shot(page, '.polar-plot canvas');
    await typeCode(page, 'D', 'float customD(float nh, float alpha) {\nfloat a = alpha;\nreturn a * nothing;\n}');
    expect(await panelText(page, 'D', '.custom-problems')).toMatch(/^Line 3:/);
    expect(await panelText(page, 'D', '.custom-status')).toMatch(/keeps your last good code/);
    const marked = await page.$$eval('.custom-panel[data-slot="D"] .cm-line', (lines) =>
      lines.map((l, i) => (l.querySelector('.cm-lintRange-error') ? i + 1 : 0)).filter(Boolean),
    );
    expect(marked).toEqual([3]);
    expect(await shot(page, '.polar-plot canvas')).toBe(good);
    expect(page.errors).toEqual([]);
  });

  it('a loop without a constant bound is refused with its message, before anything runs', async () => {
    const page = await sharedLobe();
    const before = await shot(page, '.polar-plot canvas');
    await typeCode(
      page,
      'D',
      'float customD(float nh, float alpha) {\nfloat s = 0.0;\nwhile (s < 1.0) { s += nh; }\nreturn s;\n}',
    );
    expect(await panelText(page, 'D', '.custom-problems')).toMatch(/Line 3: 'while' loops are refused/);
    expect(await shot(page, '.polar-plot canvas')).toBe(before);
    expect(page.errors).toEqual([]);
  });

  it('code in the URL is shown and waits for one click; then it runs, and runs at once on the next visit', async () => {
    const code = `${unique()}${D_TWICE_GGX}`;
    const page = await openLobe(`D=custom&${WITH_B}&codeD=${encodeURIComponent(code)}`);
    expect(await page.$eval('.custom-panel[data-slot="D"] .cm-content', (el) => el.textContent)).toContain('2.0 * a2');
    expect(await page.$eval('.custom-consent', (el) => !el.hidden)).toBe(true);
    expect((await polarPeaks(page)).A / jsPeak({})).toBeCloseTo(1, 2); // the starter draws meanwhile
    await page.click('.custom-run');
    await untilIdle(page);
    expect((await polarPeaks(page)).A / (2 * jsPeak({}))).toBeCloseTo(1, 2);
    expect(await page.$eval('.custom-consent', (el) => el.hidden)).toBe(true);
    const again = await openLobe(`D=custom&${WITH_B}&codeD=${encodeURIComponent(code)}`);
    expect(await again.$eval('.custom-consent', (el) => el.hidden)).toBe(true);
    expect((await polarPeaks(again)).A / (2 * jsPeak({}))).toBeCloseTo(1, 2);
    expect([...page.errors, ...again.errors]).toEqual([]);
    await Promise.all([page.close(), again.close()]);
  });

  it('typed code round-trips through the URL; postMessage set/get carries code that waits for the click', async () => {
    const page = await sharedLobe();
    const typed = `${unique()}${D_TWICE_GGX}`;
    await typeCode(page, 'D', typed);
    const state = await getState(page, KEY);
    expect(state.codeD).toBe(typed); // the text arrived whole, its line breaks kept
    await untilIdle(page);
    const url = page.url();
    expect(new URL(url).searchParams.has('codeD')).toBe(true);
    const query = url.slice(url.indexOf('embed.html')).replace(/^embed\.html\?w=brdf-lobe&?/, '');
    const reopened = await openLobe(query, { drawn: false }); // its state is the claim
    expect((await getState(reopened, KEY)).codeD).toBe(state.codeD);
    await reopened.close();

    // a parent frame sets code this browser has not seen: shown, not run; get returns it
    const parent = await open(browser, 'index.html');
    await parent.evaluate(
      (src) => {
        window.__inbox = [];
        window.addEventListener('message', (e) => window.__inbox.push(e.data));
        const frame = Object.assign(document.createElement('iframe'), { src, id: 'embedded' });
        frame.style.cssText = 'width: 1000px; height: 1300px; border: 0';
        document.body.replaceChildren(frame);
      },
      new URL(`embed.html?w=${KEY}&D=custom&${WITH_B}`, baseUrl()).href,
    );
    const frame = await (await parent.waitForSelector('#embedded')).contentFrame();
    await frame.waitForSelector('.custom-panel .cm-content', { timeout: WAIT_MS });
    const sent = `${unique()}${D_TWICE_GGX}`;
    const post = (m) =>
      parent.evaluate((m, o) => document.getElementById('embedded').contentWindow.postMessage(m, o), m, baseUrl());
    await post({ type: 'shading-lab:set', id: 's', state: { codeD: sent } });
    await post({ type: 'shading-lab:get', id: 'g' });
    const got = await parent
      .waitForFunction(() => window.__inbox.find((d) => d.type === 'shading-lab:state' && d.id === 'g'))
      .then((h) => h.jsonValue());
    expect(got.state.codeD).toBe(sent);
    await untilIdle(frame);
    expect(await frame.$eval('.custom-consent', (el) => !el.hidden)).toBe(true);
    expect(await frame.$eval('.cm-content', (el) => el.textContent)).toContain(sent.split('\n')[0].slice(3));
    expect(parent.errors).toEqual([]);
    await parent.close();
    expect(page.errors).toEqual([]);
  });

  it('a lost WebGL context shows a message; restored, the previous program draws again and edits run', async () => {
    const page = await sharedLobe(); // its last case: the context is lost and comes back
    await typeCode(page, 'D', D_TWICE_GGX);
    const good = await shot(page, '.polar-plot canvas');
    await page.evaluate(() => {
      const gl = document.querySelector('.lobe-3d canvas').getContext('webgl2');
      window.__lose = gl.getExtension('WEBGL_lose_context');
      window.__lose.loseContext();
    });
    const status = () => panelText(page, 'D', '.custom-status');
    await expect.poll(status, { timeout: WAIT_MS }).toMatch(/WebGL context away; it comes back by itself/); // an event
    await untilIdle(page);
    expect(await shot(page, '.polar-plot canvas')).toBe(good);
    await page.evaluate(() => window.__lose.restoreContext());
    await expect.poll(status, { timeout: WAIT_MS }).toMatch(/Running your code/);
    await untilIdle(page);
    expect(await shot(page, '.polar-plot canvas')).toBe(good);
    await typeCode(page, 'D', D_TWICE_GGX.replace('2.0 * a2', 'a2'));
    expect((await polarPeaks(page)).A / jsPeak({})).toBeCloseTo(1, 2);
    expect(page.errors.filter((e) => !/CONTEXT_LOST/i.test(e))).toEqual([]);
  });

  it('code running when the GPU takes the context away is blamed: the code before it comes back', async () => {
    const page = await openLobe(`D=custom&${WITH_B}`);
    // a GPU that gives up during the next read-back of the user's values, as it does on a shader that runs too long
    await page.evaluate(() => {
      const read = WebGL2RenderingContext.prototype.readPixels;
      WebGL2RenderingContext.prototype.readPixels = function hanging(...args) {
        if (window.__hangOnce) {
          window.__hangOnce = false;
          window.__lose = this.getExtension('WEBGL_lose_context');
          window.__lose.loseContext();
        }
        return read.apply(this, args);
      };
    });
    await typeCode(page, 'D', D_TWICE_GGX.replace('2.0 * a2', '3.0 * a2').replace('{', '{ // heavy'));
    expect((await polarPeaks(page)).A / (3 * jsPeak({}))).toBeCloseTo(1, 2); // it ran once, before the hang
    await page.evaluate(() => (window.__hangOnce = true));
    await typeCode(page, 'D', D_TWICE_GGX.replace('2.0 * a2', '4.0 * a2'));
    const status = () => panelText(page, 'D', '.custom-status');
    await expect.poll(status, { timeout: WAIT_MS }).toMatch(/while your new code was drawing/);
    await page.evaluate(() => window.__lose.restoreContext());
    await expect.poll(status, { timeout: WAIT_MS }).toMatch(/Your code was running when the GPU took/);
    await untilIdle(page);
    expect((await polarPeaks(page)).A / (3 * jsPeak({}))).toBeCloseTo(1, 2); // the code before it
    await page.click('.custom-panel[data-slot="D"] .cm-content');
    await page.keyboard.press('Enter'); // an edit: the code may run again
    await untilIdle(page);
    expect((await polarPeaks(page)).A / (4 * jsPeak({}))).toBeCloseTo(1, 2);
    expect(page.errors.filter((e) => !/CONTEXT_LOST/i.test(e))).toEqual([]);
    await page.close();
  });
});
