// The microfacet chapters (BRDF, microfacet theory, NDF, visibility) in a real Chromium.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  getState,
  launchBrowser,
  open as openSized,
  pointUntil,
  redAt,
  setControl,
  shot,
  untilIdle,
  widget,
  widgetLoaded,
  withPixels,
} from './helpers.js';
import { linearToSrgb } from '../../src/math/color.js';
import { albedoGGX } from '../../src/math/integrate.js';
import { DEG } from '../../src/math/angles.js';
import { termLabel } from '../../src/math/catalogue/index.js';
import { ndfCurves, tailsAt } from '../../src/widgets/ndf-explorer/model.js';
import { SMALL_VIEWPORT } from './harness.js';

/** A page in a small window unless a test's pixels need a size (software WebGL's cost grows with the pixels). */
const open = (browser, path, size = SMALL_VIEWPORT) => openSized(browser, path, size);

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('chapter page state', () => {
  it('round-trips through the URL under its prefix, and bad values give notices', async () => {
    const page = await open(browser, 'ndf.html?ndf.hwhm=12.5&ndf.D=ggx,beckmann&ndf.exposure=banana');
    await widget(page, 'ndf');
    const state = await getState(page, 'ndf');
    expect([state.hwhm, state.D]).toEqual([12.5, ['ggx', 'beckmann']]);
    expect(await page.$eval('.notice', (el) => el.textContent)).toMatch(/banana/);
    await setControl(page, 'Light from view (°)', 50);
    const url = page.url();
    expect(url).toMatch(/ndf\.lightTheta=50/);
    const again = await open(browser, url.slice(url.indexOf('ndf.html')));
    await widgetLoaded(again, 'ndf'); // its state is the claim, not its pictures
    expect(await getState(again, 'ndf')).toEqual(await getState(page, 'ndf'));
    expect(again.errors).toEqual([]);
    await Promise.all([page.close(), again.close()]);
  });
  it('each widget links the parity page, and the terms it uses (folded away) to their rows there', async () => {
    const page = await open(browser, 'visibility.html');
    await widgetLoaded(page, 'vis'); // its links and words are the claim
    const terms = await page.$eval('.widget-terms', (box) => ({
      shown: [...box.querySelectorAll(':scope > p a')].map((a) => [a.getAttribute('href'), a.checkVisibility()]),
      folded: [...box.querySelectorAll('details:not([open]) a')].map((a) => [a.textContent, a.checkVisibility()]),
      visibleText: box.innerText,
    }));
    expect(terms.shown).toEqual([['parity.html', true]]); // the way to the accuracy, in view
    expect(terms.folded).toContainEqual(['visibilityKelemen', false]); // the function names, in a closed <details>
    expect(terms.visibleText).not.toMatch(/visibilityKelemen|src\/math/);
    const hrefs = await page.$$eval('.widget-terms a', (as) => as.map((a) => a.getAttribute('href')));
    expect(hrefs).toContain('parity.html#fn-visibilityKelemen');
    await page.close();
    // the parity page runs only the rows of the functions linked (?only=: names a row starts with); a row's anchor
    // is its function's name, as on the whole page
    const linked = hrefs.filter((h) => h.includes('#fn-')).map((h) => h.slice(h.indexOf('#fn-') + 4));
    const parity = await open(browser, `parity.html?only=${linked.join(',')}#fn-visibilityKelemen`);
    await parity.waitForSelector('#parity-summary', { timeout: WAIT_MS });
    for (const href of hrefs.filter((h) => h.includes('#')))
      expect(await parity.$(href.slice(href.indexOf('#')))).not.toBeNull();
    await parity.close();
  });
});

describe('ndf-explorer', () => {
  it('shows five normalised NDFs, and the width slider changes the highlights and the URL', async () => {
    const page = await open(browser, 'embed.html?w=ndf-explorer');
    await widget(page, 'ndf-explorer');
    const integrals = await page.evaluate(() => globalThis.__shadingLab.widgets['ndf-explorer'].getIntegrals());
    console.log(
      `NDF normalisation: ${Object.entries(integrals)
        .map(([k, v]) => `${k} ${v.toFixed(8)}`)
        .join(', ')}`,
    );
    expect(Object.keys(integrals)).toHaveLength(5);
    for (const v of Object.values(integrals)) expect(Math.abs(v - 1)).toBeLessThan(1e-6);
    const before = await shot(page, '.sphere-grid canvas');
    await setControl(page, 'Matched half width (°)', 20);
    expect(await shot(page, '.sphere-grid canvas')).not.toBe(before);
    expect(page.url()).toMatch(/hwhm=20/);
    // the probe: hover the middle of the third sphere (GGX)
    const probe = () => page.$eval('.widget-ndf-explorer .probe', (el) => el.textContent);
    await pointUntil(page, '.sphere-grid canvas', [0.5, 0.5], async () =>
      /GGX.*n·v1\.0000.*D\(n·h\)/s.test(await probe()),
    );
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('ndf-explorer, the log plot', () => {
  it('has a legend of its own whose hover readout gives D (Home: D(0) of each NDF, as src/math has it)', async () => {
    const page = await open(browser, 'embed.html?w=ndf-explorer');
    await widget(page, 'ndf-explorer');
    const logPlot = '.widget-ndf-explorer figure.plot:nth-of-type(2)';
    const values = () => page.$$eval(`${logPlot} .u-legend .u-value`, (els) => els.map((e) => e.textContent));
    expect((await values()).length).toBe(6); // θh and the five NDFs
    const box = await (await page.$(`${logPlot} .u-over`)).boundingBox();
    await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.5);
    await expect.poll(async () => (await values())[0], { timeout: WAIT_MS }).not.toBe('—');
    // the pointer leaves before the keyboard takes over: a late layout shift under it (a loaded machine) would
    // otherwise move or hide the cursor the Home key placed
    await page.mouse.move(0, 0);
    await expect.poll(async () => (await values())[0], { timeout: WAIT_MS }).toBe('—');
    await untilIdle(page);
    await page.focus(`${logPlot} canvas`);
    await page.keyboard.press('Home');
    const curves = await page.evaluate(() => globalThis.__shadingLab.widgets['ndf-explorer'].getCurves());
    const expected = ['0.0', ...Object.values(curves).map((d) => d[0].toPrecision(3))];
    await expect.poll(values, { timeout: WAIT_MS }).toEqual(expected);
    const state = await getState(page, 'ndf-explorer');
    const named = termLabel('ndf', tailsAt(ndfCurves(state))[0].key);
    expect(await page.$eval('.widget-ndf-explorer .tail-note', (el) => el.textContent)).toMatch(
      new RegExp(`^Longest tail at a half width of 8°: ${named}\\.`),
    );
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('visibility-explorer', () => {
  it('roughness changes the Smith curves but not the implicit term', async () => {
    const page = await open(browser, 'embed.html?w=visibility-explorer&V=implicit,smithGGXCorrelated');
    await widget(page, 'visibility-explorer');
    const errs1 = await page.evaluate(() => globalThis.__shadingLab.widgets['visibility-explorer'].getWorstErrors());
    await setControl(page, 'Roughness α', 0.1);
    const errs2 = await page.evaluate(() => globalThis.__shadingLab.widgets['visibility-explorer'].getWorstErrors());
    expect(errs1.smithGGXCorrelated).toBe(0);
    expect(errs2.implicit).not.toBeCloseTo(errs1.implicit, 1); // the reference moved, the implicit term did not
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('visibility-explorer, the axes and the spheres’ note', () => {
  it('after “l, v mirrored” the plots look as that state opened fresh (the axis follows the mode)', async () => {
    const plotCanvas = '.widget-visibility-explorer figure.plot canvas';
    const page = await open(browser, 'embed.html?w=visibility-explorer');
    await widget(page, 'visibility-explorer');
    await setControl(page, 'Directions', 'l, v mirrored about n (h = n)');
    const changed = await shot(page, plotCanvas);
    const fresh = await open(browser, 'embed.html?w=visibility-explorer&config=mirror');
    await widget(fresh, 'visibility-explorer');
    await untilIdle(fresh);
    expect(changed).toBe(await shot(fresh, plotCanvas));
    expect(await page.$eval('.widget-visibility-explorer .rim-note', (el) => el.textContent)).toMatch(
      /^What to look for: the lit side.*Cook–Torrance \+\d+%/,
    );
    expect([...page.errors, ...fresh.errors]).toEqual([]);
    await Promise.all([page.close(), fresh.close()]);
  });
});

describe('energy (white furnace)', () => {
  it('renders E = 1 - ln 2 at the centre of the alpha = 1 sphere, and a near-invisible smooth sphere', async () => {
    // samples and sampleCount were removed: an old URL with them still loads
    const url = 'embed.html?w=energy&alphas=0.05,1.0&samples=256&sampleCount=4096';
    const page = await open(browser, url, { width: 900, height: 900 });
    await widget(page, 'energy'); // and idle: the spheres drawn, no frame more asked for
    const albedos = await page.evaluate(() => globalThis.__shadingLab.widgets['energy'].getAlbedos());
    console.log(
      'albedo: ' +
        albedos.map((a) => `α ${a.alpha}: E(1) ${a.atNormal.toFixed(4)}, E_avg ${a.average.toFixed(4)}`).join('; '),
    );
    expect(albedos[1].atNormal).toBeCloseTo(1 - Math.log(2), 6);
    expect(Object.keys(await getState(page, 'energy'))).toEqual(['alphas', 'compensation', 'metal', 'metalAlpha']);
    // read the rendered centres back: cell i of 2 spans half the canvas
    const png = await shot(page, '.sphere-grid canvas');
    const centres = await redAt(page, png, [
      [0.25, 0.5],
      [0.75, 0.5],
    ]);
    const expected = Math.round(linearToSrgb(1 - Math.log(2)) * 255);
    console.log(`furnace centres (8-bit): α 0.05 → ${centres[0]}, α 1 → ${centres[1]} (expected ${expected})`);
    expect(centres[0]).toBeGreaterThan(250);
    expect(Math.abs(centres[1] - expected)).toBeLessThanOrEqual(3);
    expect(page.errors).toEqual([]);
    await page.close();
  });
  it(
    'the rim of the alpha = 0.5 sphere matches albedoGGX pixel by pixel out to ' +
      "85° (E 0.872, not 64 samples' 0.959)",
    async () => {
      const page = await open(browser, 'embed.html?w=energy&alphas=0.5', { width: 900, height: 900 });
      await widget(page, 'energy'); // and idle: the spheres drawn, no frame more asked for
      const rim = rimAgainstAlbedo(await centreRow(page, await shot(page, '.sphere-grid canvas')), 0.5);
      const { at85, worst } = rim;
      console.log(
        `furnace rim α 0.5 (sphere radius ${rim.radius.toFixed(1)} px): the pixel at n·v ` +
          `${at85.nv.toFixed(4)} reads ${at85.got}, albedoGGX gives ${at85.expected.toFixed(1)}; ` +
          `worst from 70° ${JSON.stringify(worst)}`,
      );
      expect(Math.acos(rim.at85.nv) / DEG).toBeGreaterThan(84.5);
      expect(Math.abs(rim.at85.got - rim.at85.expected)).toBeLessThanOrEqual(2);
      expect(rim.worst.diff).toBeLessThanOrEqual(2.5);
      expect(rim.at85.got).toBeLessThan(linearToSrgb(0.959) * 255 - 5); // what 64 Hammersley samples gave
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );
});

/** The red channel along the middle row of a base64 PNG, and its size. */
function centreRow(page, png) {
  return withPixels(page, png, (image) => {
    const y = Math.floor(image.height / 2);
    const red = Array.from({ length: image.width }, (_, x) => image.data[(y * image.width + x) * 4]);
    return { width: image.width, height: image.height, y, red };
  });
}

/**
 * Each pixel of the row right of the centre, from 70° to the silhouette, against sRGB(albedoGGX(n·v)) at its
 * centre: one furnace sphere fills the square canvas but for the camera's margin (half extent 1.08, sphere-grid.js).
 */
function rimAgainstAlbedo(row, alpha) {
  const radius = Math.min(row.width, row.height) / 2 / 1.08;
  const dy = (row.y + 0.5 - row.height / 2) / radius;
  const target = Math.cos(85 * DEG);
  let worst = { diff: 0 };
  let at85 = null;
  for (let x = Math.ceil(row.width / 2); x < row.width; x++) {
    const d = Math.hypot((x + 0.5 - row.width / 2) / radius, dy);
    if (d > 1 - 0.75 / radius) break; // pixels the silhouette may cut (half a diagonal from their centre)
    const nv = Math.sqrt(1 - d * d);
    if (nv > Math.cos(70 * DEG)) continue;
    const expected = linearToSrgb(albedoGGX(nv, alpha)) * 255;
    const pixel = { nv, got: row.red[x], expected, diff: Math.abs(row.red[x] - expected) };
    if (pixel.diff > worst.diff) worst = pixel;
    if (!at85 || Math.abs(nv - target) < Math.abs(at85.nv - target)) at85 = pixel;
  }
  return { radius, worst, at85 };
}

describe('microfacets', () => {
  it("the ray-traced share of lit microfacets agrees with Smith's G1", async () => {
    // one page: a new kind of surface is a new surface and a new sweep (microfacets.js rebuild)
    const page = await open(browser, 'embed.html?w=microfacets&kind=beckmann&alpha=0.6');
    await widget(page, 'microfacets');
    for (const kind of ['beckmann', 'ggx']) {
      await page.evaluate((kind) => globalThis.__shadingLab.widgets.microfacets.update({ kind }), kind);
      expect((await getState(page, 'microfacets')).kind).toBe(kind);
      await page.waitForFunction(() => globalThis.__shadingLab.widgets.microfacets.getG1().complete, {
        timeout: WAIT_MS,
      });
      const g = await page.evaluate(() => globalThis.__shadingLab.widgets.microfacets.getG1());
      const worst = Math.max(...g.measured.map((m, i) => Math.abs(m - g.smith[i])));
      console.log(`microsurface ${kind} α 0.6: worst |ray-traced G1 − Smith G1| over 0–85° = ${worst.toFixed(4)}`);
      expect(worst).toBeLessThan(0.03);
    }
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('anisotropic-microsurface', () => {
  it("ray-traced G1 of a 3-D Gaussian surface vs Smith's anisotropic Beckmann G1, 13 azimuths", async () => {
    const key = 'anisotropic-microsurface';
    const page = await open(browser, `embed.html?w=${key}&alphaX=0.7&alphaY=0.25&theta=80`);
    await widget(page, key);
    const g1 = () => page.evaluate((k) => globalThis.__shadingLab.widgets[k].getG1(), key);
    await page.waitForFunction((k) => globalThis.__shadingLab.widgets[k].getG1().complete, { timeout: WAIT_MS }, key);
    const g = await g1();
    const worst = Math.max(...g.measured.map((m, i) => Math.abs(m - g.smith[i])));
    console.log(`3-D microsurface (0.7, 0.25) at 80°: worst |ray-traced G1 − Smith G1| over 13 azimuths = ${worst}`);
    expect(worst).toBeLessThan(0.02); // 12 000 seeded rays an azimuth: a standard error under ~0.007
    expect(g.measured[6] - g.measured[0]).toBeGreaterThan(0.2); // along b (φ = 90°) far less shadowed than along t
    const before = await shot(page, 'canvas.aniso-microsurface');
    await setControl(page, 'Light azimuth from t, φ (°)', 120);
    await untilIdle(page);
    expect(await shot(page, 'canvas.aniso-microsurface')).not.toBe(before);
    expect(await page.$eval('.widget-anisotropic-microsurface caption', (c) => c.textContent)).toMatch(/φ 120°/);
    expect(page.errors).toEqual([]);
    await page.close();
  });
  it('sits on the microfacets chapter page under its prefix', async () => {
    const page = await open(browser, 'microfacets.html?aniso-surface.phi=45');
    await widgetLoaded(page, 'aniso-surface'); // its state and the page's errors are the claim, not its pictures
    expect((await getState(page, 'aniso-surface')).phi).toBe(45);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('brdf-lobe', () => {
  it('drags the light on the polar plot, and switching D off changes the lobe', async () => {
    const page = await open(browser, 'embed.html?w=brdf-lobe');
    await widget(page, 'brdf-lobe');
    const box = await (await page.$('.polar-plot canvas')).boundingBox();
    // press on the light handle's side, drag towards the normal
    await page.mouse.move(box.x + box.width * 0.25, box.y + box.height * 0.4);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.45, box.y + box.height * 0.2, { steps: 4 });
    await page.mouse.up();
    const theta = (await getState(page, 'brdf-lobe')).lightTheta;
    expect(theta).toBeGreaterThan(0);
    expect(theta).toBeLessThan(45);
    const before = await shot(page, '.polar-plot canvas');
    await setControl(page, 'Use D (distribution)', false);
    expect(await shot(page, '.polar-plot canvas')).not.toBe(before);
    await setControl(page, 'Compare with BRDF B', true);
    expect(await page.$$eval('.half-diff-row.single', (els) => els.length)).toBe(0);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
