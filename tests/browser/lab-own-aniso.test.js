// The user's anisotropic D and V (customDAniso, customVAniso) as the material lab's stretched lobe ("Stretched D",
// "Stretched V"), in Chromium, under the punctual light alone, where the lab's approximation is exact (π f c_light
// (n·l)): their starters render as float64 anisotropic GGX with its height-correlated Smith V (src/math/anisotropic.js,
// lab-aniso-truth.js) and as the lab's own stretched lobe from the catalogue; their panels show the checks (the
// normalisation over the 2-D hemisphere, the weak furnace); code that does not compile, in the checks' program or
// only in the lab's (a name of the lab's taken), gives a message on the user's line and keeps the last picture.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser, open, typeCode, untilIdle, widget } from './helpers.js';
import { anisotropicAlphas } from '../../src/math/anisotropic.js';
import { RES, TEXELS, blockMean, frameAround, lobeCos, normalAt, spherical } from './lab-aniso-truth.js';

const ALPHA = 0.25;
const A = 0.8;
const POLE = { theta: 50, phi: 90 };
const ROTATION = 20;
const LIGHT = { theta: 40, phi: 20 };
const QUERY =
  `material=manual&f0=1&F=one&layers=specular&alpha=${ALPHA}&anisotropy=${A}&anisotropyModel=burley2012` +
  `&tangentField=around&tangentTheta=${POLE.theta}&tangentPhi=${POLE.phi}&tangentRotation=${ROTATION}` +
  `&ambient=0&env=0&area=0&punctual=1&lightTheta=${LIGHT.theta}&lightPhi=${LIGHT.phi}&cLight=1&refSamples=128` +
  '&anisoD=custom&anisoV=custom';
const PAIR = anisotropicAlphas(ALPHA, A, 'burley2012');
const frameAt = frameAround(POLE, ROTATION);
const L = spherical(LIGHT.theta, LIGHT.phi);
const truth = (pair) => TEXELS.map((t) => blockMean(t, (x) => Math.PI * lobeCos(frameAt(normalAt(x)), L, pair)));

let browser;
let page;
beforeAll(async () => {
  browser = await launchBrowser();
  // the reference is exact for the punctual light from its first batch: one batch of 8, not 128 for nothing
  page = await open(browser, `embed.html?w=material-lab&${QUERY}`, { width: 800, height: 1400, maxSamples: 8 });
  await widget(page, 'material-lab');
  for (const slot of ['DAniso', 'VAniso']) await page.waitForSelector(`.custom-panel[data-slot="${slot}"] .cm-content`);
  await untilIdle(page);
});
afterAll(async () => {
  await browser?.close();
});

const lab = (call, ...args) =>
  page.evaluate((c, a) => globalThis.__shadingLab.widgets['material-lab'][c](...a), call, args);
/** The approximation's red channel, whole. */
const approx = () => page.evaluate(() => Array.from(globalThis.__shadingLab.widgets['material-lab'].read('approx')));
/** The red channel's 3 × 3 means around TEXELS of an image read by approx(). */
const atTexels = (image) =>
  TEXELS.map(([i, j]) => {
    let sum = 0;
    for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) sum += image[((j + dj) * RES + i + di) * 4];
    return sum / 9;
  });
/** Types `code` into the slot's editor, then brings the images back into view (the lab draws only what is seen). */
async function typed(slot, code) {
  await typeCode(page, slot, code);
  await page.evaluate(() => window.scrollTo(0, 0));
  await untilIdle(page);
}
const panelText = (slot, selector) =>
  page.$eval(`.custom-panel[data-slot="${slot}"] ${selector}`, (el) => el.textContent);

describe('material lab: your anisotropic D and V', () => {
  it('the starters render as float64 anisotropic GGX (3e-3) and as the catalogue’s stretched lobe (1e-3)', async () => {
    const own = await approx();
    const got = atTexels(own);
    const want = truth(PAIR);
    console.log(`your D and V: lab ${got.map((x) => x.toFixed(4))}; float64 ${want.map((x) => x.toFixed(4))}`);
    got.forEach((x, k) => expect(Math.abs(x - want[k])).toBeLessThan(3e-3 * want[k] + 2e-4));
    const iso = truth([ALPHA, ALPHA]);
    expect(want.some((x, k) => Math.abs(x - iso[k]) > 0.1 * x)).toBe(true); // the isotropic lobe would fail
    // the checks of each panel, on the user's code
    await page.waitForFunction(
      () =>
        [...document.querySelectorAll('.custom-panel .custom-checks')].every((el) => /Against/.test(el.textContent)),
      { timeout: WAIT_MS, polling: 500 },
    );
    const vChecks = await panelText('VAniso', '.custom-checks');
    console.log(`the VAniso panel's checks: ${vChecks}`);
    expect(vChecks).toMatch(/G = V \(n·l\)\(n·v\) from .* to .*; 0 outside \[0, 1\]/);
    expect(vChecks).toMatch(/Against Smith GGX, height-correlated, anisotropic: largest difference/);
    const checks = await panelText('DAniso', '.custom-checks');
    console.log(`the DAniso panel's checks: ${checks}`);
    expect(checks).toMatch(/∫ D\(m\)\(n·m\) dω should be 1; worst 1 /);
    expect(checks).toMatch(/Weak white furnace \(Heitz 2014\) with GGX’s Λ: .* should be 1 at every v; worst 1/);
    expect(await page.$$eval('.custom-panel .custom-checks .check-fail', (els) => els.length)).toBe(0);
    // the lab's own stretched lobe (the catalogue's ggxAniso and smithGGXCorrelatedAniso), in the same page
    await lab('update', { anisoD: 'chosen', anisoV: 'chosen' });
    await untilIdle(page);
    const builtIn = await approx();
    let worst = 0;
    for (let i = 0; i < own.length; i += 4)
      worst = Math.max(worst, Math.abs(own[i] - builtIn[i]) / (builtIn[i] + 1e-3));
    console.log(`your starters against the catalogue's lobe: worst relative difference ${worst.toExponential(2)}`);
    expect(worst).toBeLessThan(1e-3);
    expect(await page.$('.custom-panel[data-slot="DAniso"]')).toBeNull(); // no panel for a term not drawn
    expect(page.errors).toEqual([]);
  });

  it('code that does not compile gives a message on its line and keeps the picture', async () => {
    await lab('update', { anisoD: 'custom', anisoV: 'custom' });
    await page.waitForSelector('.custom-panel[data-slot="DAniso"] .cm-content', { timeout: WAIT_MS });
    await untilIdle(page);
    // a half-width D: the picture changes (the typed code draws), and it is the one kept below
    const halved = (
      await page.evaluate(() => globalThis.__shadingLab.widgets['material-lab'].getState().codeDAniso)
    ).replace('return 1.0 / (PI', 'return 0.5 / (PI');
    await typed('DAniso', halved);
    const before = await approx();
    const want = truth(PAIR).map((x) => x / 2);
    atTexels(before).forEach((x, k) => expect(Math.abs(x - want[k])).toBeLessThan(3e-3 * want[k] + 2e-4));
    // an undeclared name on line 2: the checks' program refuses it
    await typed('DAniso', 'float customDAniso(vec3 h, vec2 alpha) {\nreturn h.z * missing;\n}');
    expect(await panelText('DAniso', '.custom-problems')).toMatch(/^Line 2: .*missing/);
    expect(await panelText('DAniso', '.custom-status')).toMatch(/keeps your last good code/);
    expect(await approx()).toEqual(before);
    // a name of the lab's program (its pair's accessor) taken: runs in the checks, refused in the lab's program
    const clash = `vec2 alphaPair() { return vec2(1.0); }\n${halved.replace('0.5 / (PI', '0.25 / (PI')}`;
    await typed('DAniso', clash);
    expect(await panelText('DAniso', '.custom-problems')).toMatch(/alphaPair/);
    expect(await panelText('DAniso', '.custom-status')).toMatch(/keeps your last good code/);
    expect(await approx()).toEqual(before);
    expect(page.errors).toEqual([]);
  });
});
