// The OpenPBR chapter (issue 29) in Chromium: the page's brdf-lobe in OpenPBR mode shows each layer's part of the
// lobe at (l, v), each against openPbrLayers of src/math/openpbr.js (float64, called here on the material the
// page's state names); a control changes them as the math says; the tour's step sets the mode up; the chapter's
// two exercises are graded from the math through their controls.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, getState, launchBrowser, open, setControl, untilIdle, widget } from './helpers.js';
import { openPbrLayers } from '../../src/math/openpbr.js';
import { srgbToLinear } from '../../src/math/color.js';
import { f82SchlickGap } from '../../src/exercises/graders/f82-schlick-gap.js';

const DEG = Math.PI / 180;
const LAYERS = ['specular', 'diffuse', 'metal', 'coat', 'fuzz'];
const Y = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b; // Rec. 709 luminance, written out here
const linear = (hex) => [1, 3, 5].map((i) => srgbToLinear(parseInt(hex.slice(i, i + 2), 16) / 255));

/** openPbrLayers' parts at the state's light and view (the plane of incidence at φ = 0), as the widget's keys. */
function expectedParts(s) {
  const l = [-Math.sin(s.lightTheta * DEG), 0, Math.cos(s.lightTheta * DEG)];
  const v = [Math.sin(s.viewTheta * DEG), 0, Math.cos(s.viewTheta * DEG)];
  const material = {
    base_color: linear(s.base_color),
    base_metalness: s.base_metalness,
    specular_color: linear(s.specular_color),
    specular_roughness: s.specular_roughness,
    coat_weight: s.coat_weight,
    coat_roughness: s.coat_roughness,
    fuzz_weight: s.fuzz_weight,
    fuzz_roughness: s.fuzz_roughness,
  };
  return openPbrLayers(l, v, material);
}

/** The readout's layer rows: { layer: [R, G, B, Y] } as printed. */
const readRows = (page) =>
  page.$$eval('.openpbr-layers tr[data-layer]', (rows) =>
    Object.fromEntries(rows.map((r) => [r.dataset.layer, [...r.cells].slice(1, 5).map((c) => Number(c.textContent))])),
  );

/** Each printed figure reads the float64 value to its printed digits (3 significant in RGB, 4 in Y). */
function expectRowsMatch(rows, parts) {
  for (const k of LAYERS) {
    const want = [...parts[k], Y(parts[k])];
    want.forEach((x, i) => expect(rows[k][i], `${k}[${i}]`).toBe(Number(x.toPrecision(i < 3 ? 3 : 4))));
  }
  const whole = [0, 1, 2].map((c) => LAYERS.reduce((s, k) => s + parts[k][c], 0));
  expect(rows.all[3]).toBe(Number(Y(whole).toPrecision(4)));
}

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('the material of today (today.html): brdf-lobe in OpenPBR mode', () => {
  it('each layer’s part at (l, v) is openPbrLayers’ (float64); the coat switched off, its gloss is back', async () => {
    const page = await open(browser, 'today.html', { width: 1000, height: 800 });
    await widget(page, 'lobe');
    let state = await getState(page, 'lobe');
    expect(state).toMatchObject({ brdf: 'openpbr', coat_weight: 1, base_color: '#b22222', viewTheta: 45 });
    let rows = await readRows(page);
    expectRowsMatch(rows, expectedParts(state));
    // the chapter's sentence: in the mirror direction the coat makes 98.7% of the lobe
    expect(rows.coat[3] / rows.all[3]).toBeCloseTo(0.987, 3);
    const polar = await page.$eval('.widget-brdf-lobe canvas[aria-label^="Polar plot"]', (c) => c.ariaLabel);
    expect(polar).toMatch(/coat peaks at 45\.5°/);

    await setControl(page, 'coat_weight', 0, '.widget-brdf-lobe');
    state = await getState(page, 'lobe');
    expect(state.coat_weight).toBe(0);
    rows = await readRows(page);
    expectRowsMatch(rows, expectedParts(state));
    expect(rows.coat[3]).toBe(0);
    expect(rows.specular[3]).toBeGreaterThan(0.1); // 0.124 /sr: the base's own gloss, no longer under the coat
    expect(page.errors).toEqual([]);
    await page.close();
  }, 240_000);

  it('the tour’s step sets the mode up with the layers shown, at the view its words speak of', async () => {
    const page = await open(browser, 'tour.html#today-openpbr-layers', { width: 1000, height: 800 });
    await page.waitForFunction(
      () => globalThis.__shadingLab?.tour?.ready && globalThis.__shadingLab.tour.id === 'today-openpbr-layers',
      { timeout: WAIT_MS },
    );
    await untilIdle(page);
    const rows = await readRows(page);
    // "Seen from 0°, 88% of the light is the base's diffuse lobe"
    expect(rows.diffuse[3] / rows.all[3]).toBeCloseTo(0.88, 2);
    expect(page.errors).toEqual([]);
    await page.close();
  }, 240_000);
});

describe('the chapter’s exercises, through their controls', () => {
  it('which layer: the coat is wrong at 20°, the metal right; copper’s gap is the grader’s', async () => {
    const page = await open(browser, 'exercises.html#openpbr-which-layer', { width: 860, height: 640, maxSamples: 8 });
    const ready = (id) => globalThis.__shadingLab?.exercise?.id === id && globalThis.__shadingLab.exercise.ready;
    await page.waitForFunction(ready, {}, 'openpbr-which-layer');
    await untilIdle(page);
    expect(await page.$('.exercise-widget .openpbr-layers')).toBeNull(); // the parts are hidden
    const check = async (value) => {
      await page.click(`input[name=answer][value=${value}]`);
      await page.click('.exercise-check');
      await page.waitForSelector('.exercise-feedback.ok, .exercise-feedback.wrong');
      return page.$eval('.exercise-feedback', (el) => ({ ok: el.classList.contains('ok'), text: el.textContent }));
    };
    const wrong = await check('coat');
    expect(wrong.ok).toBe(false);
    expect(wrong.text).toMatch(/The coat makes only 12\.8% of the lobe/);
    expect((await check('metal')).ok).toBe(true);

    await page.click('#exercise-list a[href="#f82-grazing-copper"]');
    await page.waitForFunction(ready, {}, 'f82-grazing-copper');
    await untilIdle(page);
    const { gap } = f82SchlickGap('copper', 'b', 80);
    await page.type('#exercise-answer', gap.toFixed(2));
    await page.click('.exercise-check');
    await page.waitForSelector('.exercise-feedback.ok, .exercise-feedback.wrong');
    expect(await page.$eval('.exercise-feedback', (el) => el.classList.contains('ok'))).toBe(true);
    expect(page.errors).toEqual([]);
    await page.close();
  }, 240_000);
});
