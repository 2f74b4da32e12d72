// The BRDF lobe with the light and the view each at its own azimuth (issue 28, beyond the talk), in a real
// Chromium: the 3-D lobe as drawn (its vertices and arrows, in the patch's frame) against f = F·D·V / 4 written
// here from src/math's anisotropic terms, with l and v built from their angles in the tangent frame directly; the
// azimuths set by their controls and by the polar plot's keys, and an old link's `phi` read as the light's.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, getState, launchBrowser, open, setControl, untilIdle, widget } from './helpers.js';
import {
  anisotropicAlphas,
  ndfBeckmannAniso,
  ndfGGXAniso,
  visibilitySmithGGXCorrelatedAniso,
} from '../../src/math/anisotropic.js';
import { fresnelSchlick } from '../../src/math/fresnel.js';
import { DEG } from '../../src/math/angles.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const NDF = { ggx: ndfGGXAniso, beckmann: ndfBeckmannAniso };
/** A direction from its polar angle and its azimuth from t (degrees), in the tangent frame. */
const spherical = (theta, phi) => [
  Math.sin(theta * DEG) * Math.cos(phi * DEG),
  Math.sin(theta * DEG) * Math.sin(phi * DEG),
  Math.cos(theta * DEG),
];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** f(l, v) of the state's A (anisotropic D, height-correlated anisotropic Smith GGX, Schlick), all in src/math. */
function brdfOf(s, l, v) {
  if (!(l[2] > 0 && v[2] > 0)) return 0;
  const [ax, ay] = anisotropicAlphas(s.alpha, s.anisotropy, s.convention);
  const sum = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const h = sum.map((x) => x / Math.hypot(...sum));
  const D = NDF[s.D](...h, ax, ay);
  const V = visibilitySmithGGXCorrelatedAniso(...l, ...v, ax, ay);
  return (fresnelSchlick(s.f0, dot(l, h)) * D * V) / 4;
}

/** The state's l and v: the light at (θl, φl); the view at θv, its azimuth φl + 180° + Δφ (θv < 0: the far side). */
const lightAndView = (s) => [
  spherical(s.lightTheta, s.lightPhi),
  spherical(Math.abs(s.viewTheta), s.lightPhi + (s.viewTheta < 0 ? 0 : 180) + s.viewPhi),
];

/** The drawn lobe and arrows against src/math; returns the largest relative error over the lobe's vertices. */
async function checkDrawn(page) {
  const s = await getState(page, 'brdf-lobe');
  const [l, v] = lightAndView(s);
  const drawn = await page.evaluate(() => globalThis.__shadingLab.widgets['brdf-lobe'].getLobe3d());
  for (const [key, w] of [
    ['l', l],
    ['v', v],
  ])
    drawn.arrows[key].forEach((x, i) => expect(x, `${key}[${i}] at ${JSON.stringify(s)}`).toBeCloseTo(w[i], 6));
  const peak = Math.max(...drawn.lobe.map((p) => p.value));
  let worst = 0;
  for (const { dir, value } of drawn.lobe) worst = Math.max(worst, Math.abs(value - brdfOf(s, l, dir)) / peak);
  expect(peak).toBeGreaterThan(0);
  return worst;
}

describe('brdf-lobe, the light and the view each at its own azimuth', () => {
  it('draws f(l, v) of src/math’s anisotropic GGX, Beckmann for any pair (φl, Δφ); set by keys, controls', async () => {
    const page = await open(browser, 'embed.html?w=brdf-lobe&anisotropy=0.7&alpha=0.35&lightTheta=50&viewTheta=35');
    await widget(page, 'brdf-lobe');
    await setControl(page, 'Light azimuth φl from t (°)', 30);
    await setControl(page, 'View azimuth Δφ off the plane of incidence (°)', 70);
    expect(await checkDrawn(page)).toBeLessThan(1e-5);
    // the polar plot's keys: Page Up turns the light by 5°, ] the view, both wrapped
    await page.focus('.widget-brdf-lobe canvas[aria-label^="Polar plot"]');
    await page.keyboard.press('PageUp');
    await page.keyboard.press(']');
    await untilIdle(page);
    expect(await getState(page, 'brdf-lobe')).toMatchObject({ lightPhi: 35, viewPhi: 75 });
    await page.keyboard.down('Shift');
    await page.keyboard.press('BracketLeft'); // Shift: 1°
    await page.keyboard.up('Shift');
    await untilIdle(page);
    expect(await getState(page, 'brdf-lobe')).toMatchObject({ lightPhi: 35, viewPhi: 74 });
    expect(await checkDrawn(page)).toBeLessThan(1e-5);
    const errors = [];
    for (const pair of [
      { lightPhi: 0, viewPhi: 0, viewTheta: 60 },
      { lightPhi: 90, viewPhi: -90, viewTheta: 20 },
      { lightPhi: 123, viewPhi: 180, viewTheta: -40 },
      { lightPhi: 300, viewPhi: 45, viewTheta: 75, D: 'beckmann', convention: 'gltf' },
    ]) {
      await page.evaluate((p) => globalThis.__shadingLab.widgets['brdf-lobe'].update(p), pair);
      await untilIdle(page);
      errors.push(await checkDrawn(page));
    }
    console.log(`3-D lobe against src/math, largest error / peak: ${errors.map((e) => e.toExponential(1))}`);
    expect(Math.max(...errors)).toBeLessThan(1e-5);
    const words = await page.$eval('.widget-brdf-lobe canvas[aria-label^="3-D lobe"]', (el) =>
      el.getAttribute('aria-label'),
    );
    expect(words).toContain('300° about n from the tangent t (the dark red arrow); the view is 45° off it, at 165°');
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('reads an old link’s plane azimuth `phi` as the light’s azimuth, without a notice', async () => {
    const page = await open(browser, 'embed.html?w=brdf-lobe&phi=60&anisotropy=0.5');
    await widget(page, 'brdf-lobe');
    expect(await getState(page, 'brdf-lobe')).toMatchObject({ lightPhi: 60, viewPhi: 0 });
    expect(await page.$$('.widget-brdf-lobe .notice')).toHaveLength(0);
    expect(await checkDrawn(page)).toBeLessThan(1e-5);
    // the next change writes the link under the current names
    await setControl(page, 'View azimuth Δφ off the plane of incidence (°)', 10);
    await expect.poll(() => page.url(), { timeout: WAIT_MS }).toMatch(/lightPhi=60/);
    expect(page.url()).not.toMatch(/[?&]phi=/);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
