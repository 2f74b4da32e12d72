// The anisotropic views of issue 28 in a real Chromium: the NDF explorer's anisotropy control (spheres whose
// highlight stretches along the tangent, slope maps, half widths per axis) and the visibility explorer's G1
// against azimuth, each against src/math or a closed form.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser, open, setControl, shot, untilIdle, widget, withPixels } from './helpers.js';
import { ndfHalfWidthsAlongAxes } from '../../src/math/anisotropic-width.js';
import { anisotropicAlphas, ndfGGXAniso } from '../../src/math/anisotropic.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';
import { DEG } from '../../src/math/angles.js';
import { lobePeak, lobeScene } from '../../src/widgets/brdf-lobe/model.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/**
 * The highlight's extent on sphere i of `count` (pixels with red above 200 within 0.4 of the cell's width of its
 * centre, which leaves out the labels drawn over the picture): [width, height] in pixels.
 */
const highlightExtent = (page, png, i, count) =>
  withPixels(
    page,
    png,
    `(image) => {
      const w = image.width / ${count};
      const [cx, cy, r] = [w * (${i} + 0.5), image.height / 2, 0.4 * Math.min(w, image.height)];
      let [minX, maxX, minY, maxY] = [Infinity, -Infinity, Infinity, -Infinity];
      for (let y = Math.ceil(cy - r); y < cy + r; y++)
        for (let x = Math.ceil(cx - r); x < cx + r; x++)
          if (image.data[(y * image.width + x) * 4] > 200) {
            [minX, maxX] = [Math.min(minX, x), Math.max(maxX, x)];
            [minY, maxY] = [Math.min(minY, y), Math.max(maxY, y)];
          }
      return [maxX - minX + 1, maxY - minY + 1];
    }`,
  );

describe('ndf-explorer, anisotropy', () => {
  it('stretches GGX’s highlight along the tangent (left to right); states the half widths of src/math', async () => {
    // the light at the view: the isotropic highlight is a round spot at the sphere's centre
    // five spheres in one row, the highlight's shape measured per cell: a size the claim needs
    const size = { width: 1280, height: 900 };
    const page = await open(browser, 'embed.html?w=ndf-explorer&exposure=0.5&lightTheta=0', size);
    await widget(page, 'ndf-explorer');
    const sphere = '.widget-ndf-explorer .sphere-grid canvas';
    const [w0, h0] = await highlightExtent(page, await shot(page, sphere), 2, 5); // GGX, third of five
    expect(Math.abs(w0 - h0) / h0).toBeLessThan(0.15); // isotropic: as wide as high
    await setControl(page, 'Anisotropy (GGX, Beckmann)', 0.8);
    await expect
      .poll(async () => (await highlightExtent(page, await shot(page, sphere), 2, 5))[0], { timeout: WAIT_MS })
      .toBeGreaterThan(1.4 * w0);
    const [w1, h1] = await highlightExtent(page, await shot(page, sphere), 2, 5);
    console.log(`GGX highlight, isotropic ${w0} × ${h0} px, anisotropy 0.8 ${w1} × ${h1} px`);
    expect(w1 / h1).toBeGreaterThan(1.8 * (w0 / h0));
    // the note: Burley's pair at GGX's matched α, and the half widths along t and b (src/math, bisection)
    const alpha = matchNdfWidths(8).ggx.alpha;
    const pair = anisotropicAlphas(alpha, 0.8, 'burley2012');
    const [t, b] = ndfHalfWidthsAlongAxes(ndfGGXAniso, ...pair);
    const note = await page.$eval('.widget-ndf-explorer .anisotropy-note', (el) => el.textContent);
    expect(note).toContain(`GGX, anisotropic ${t.toFixed(1)}° along the tangent, ${b.toFixed(1)}° along the bitangent`);
    expect(t).toBeGreaterThan(8);
    expect(b).toBeLessThan(8);
    // the conventions differ: glTF keeps αy = α
    await setControl(page, 'Anisotropy convention', 'glTF KHR_materials_anisotropy');
    expect(page.url()).toMatch(/convention=gltf/);
    const [gx, gy] = anisotropicAlphas(matchNdfWidths(8).beckmann.alpha, 0.8, 'gltf');
    expect(await page.$eval('.widget-ndf-explorer .anisotropy-note', (el) => el.textContent)).toContain(
      `glTF KHR_materials_anisotropy (${gx.toPrecision(3)}, ${gy.toPrecision(3)})`,
    );
    // the slope maps, described for screen readers with their pairs
    const maps = await page.$$eval('.widget-ndf-explorer .slope-map canvas', (els) =>
      els.map((el) => el.getAttribute('aria-label') ?? el.textContent),
    );
    expect(maps).toHaveLength(2);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('visibility-explorer, G1 against azimuth', () => {
  it('is Smith’s G1 at the projected roughness α(φ): the closed form 2 / (1 + √(1 + α(φ)² tan²θ))', async () => {
    const page = await open(browser, 'embed.html?w=visibility-explorer');
    await widget(page, 'visibility-explorer');
    await setControl(page, 'Anisotropy (azimuth plot)', 0.5);
    await setControl(page, 'Roughness α', 0.4);
    const curves = await page.evaluate(() => globalThis.__shadingLab.widgets['visibility-explorer'].getAzimuthCurves());
    const [ax, ay] = anisotropicAlphas(0.4, 0.5, 'burley2012');
    const tan2 = Math.tan(60 * DEG) ** 2;
    for (const phi of [0, 30, 45, 90, 135, 180]) {
      const a2 = (Math.cos(phi * DEG) * ax) ** 2 + (Math.sin(phi * DEG) * ay) ** 2;
      expect(curves['GGX, anisotropic'][phi]).toBeCloseTo(2 / (1 + Math.sqrt(1 + a2 * tan2)), 10);
    }
    expect(curves['GGX, anisotropic'][0]).toBeCloseTo(curves['GGX, isotropic at αx'][0], 12);
    expect(curves['GGX, anisotropic'][90]).toBeCloseTo(curves['GGX, isotropic at αy'][0], 12);
    // no anisotropy: flat
    await setControl(page, 'Anisotropy (azimuth plot)', 0);
    await untilIdle(page);
    const flat = await page.evaluate(() => globalThis.__shadingLab.widgets['visibility-explorer'].getAzimuthCurves());
    expect(Math.max(...flat['GGX, anisotropic']) - Math.min(...flat['GGX, anisotropic'])).toBeLessThan(1e-12);
    expect(await page.$eval('.widget-visibility-explorer .azimuth-note', (el) => el.textContent)).toMatch(
      /projected on the direction’s azimuth.*Heitz 2014/,
    );
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('brdf-lobe, the plane of incidence at any azimuth', () => {
  it('turns the plane with φl and stretches A along the tangent; the polar plot’s peak is src/math’s', async () => {
    const page = await open(browser, 'embed.html?w=brdf-lobe');
    await widget(page, 'brdf-lobe');
    const lobe3d = '.widget-brdf-lobe canvas[aria-label^="3-D lobe"]';
    const before = await shot(page, lobe3d);
    await setControl(page, 'A: anisotropy (GGX, Beckmann)', 0.8);
    await setControl(page, 'Light azimuth φl from t (°)', 90);
    await expect.poll(() => shot(page, lobe3d), { timeout: WAIT_MS }).not.toBe(before);
    const state = await page.evaluate(() => globalThis.__shadingLab.widgets['brdf-lobe'].getState());
    expect([state.lightPhi, state.anisotropy]).toEqual([90, 0.8]);
    const scene = lobeScene(state);
    const [theta, value] = lobePeak(scene.lobeA);
    const label = (sel) => page.$eval(sel, (el) => el.getAttribute('aria-label'));
    const polar = await page.$$eval('.widget-brdf-lobe canvas[aria-label^="Polar plot"]', (els) =>
      els.map((el) => el.getAttribute('aria-label')),
    );
    expect(polar[0]).toContain(`A peaks at ${theta.toFixed(1)}° (${value.toPrecision(3)} /sr)`);
    const words = await label(lobe3d);
    expect(words).toContain("the light's azimuth, 90° about n from the tangent t");
    expect(words).toMatch(/A is anisotropic, \(αx, αy\) = \([\d.]+, [\d.]+\): its lobe stretches along t/);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
