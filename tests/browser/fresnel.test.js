// The Fresnel chapter in a real Chromium: widgets, URL state, notices, zone shares, idling, no WebGL2.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  afterFrames,
  distinctColors,
  getState,
  launchBrowser,
  open,
  setControl,
  shot,
  untilIdle,
  widget,
  withPixels,
} from './helpers.js';
import { defaultState } from '../../src/core/framework/state.js';
import { sphereZoneFractions } from '../../src/math/zones.js';
import { schema } from '../../src/widgets/fresnel-zones/schema.js';
import { weightedSphereShares } from '../support/zone-shares.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const CANVAS = '.widget-fresnel-zones canvas';

/** @type {Promise<import('puppeteer-core').Page> | undefined} */
let kept;
/**
 * One page of fresnel-zones alone, for the cases that read what a state draws or computes (a page load compiles the
 * widget's programs again); opened by the first case that asks, so that each still runs alone (-t).
 */
const keptZones = () =>
  (kept ??= open(browser, 'embed.html?w=fresnel-zones').then(async (page) => {
    await widget(page, 'fresnel-zones');
    return page;
  }));
/** The kept page set to `state` (the rest at its defaults, as a page opened with only `state` in its URL), idle. */
async function zonesIn(state) {
  const page = await keptZones();
  await page.evaluate((s) => globalThis.__shadingLab.widgets['fresnel-zones'].update(s), {
    ...defaultState(schema),
    ...state,
  });
  await untilIdle(page);
  return page;
}
/** @type {Promise<import('puppeteer-core').Page> | undefined} */
let chapter;
/** fresnel.html, for its two cases (the idle page first where both run; a page load mounts its three widgets). */
const keptChapter = () =>
  (chapter ??= open(browser, 'fresnel.html').then(async (page) => {
    await widget(page, 'zones');
    return page;
  }));
afterAll(async () => Promise.all([(await kept)?.close(), (await chapter)?.close()]));

describe('fresnel-zones', () => {
  it('a GUI change changes the pixels, and the URL holds the new state', async () => {
    const page = await zonesIn({});
    const before = await shot(page, CANVAS);
    await setControl(page, 'Mode', 'Zones of n·v');
    expect(await shot(page, CANVAS)).not.toBe(before);
    await setControl(page, 'Shape', 'Torus knot');
    const url = page.url();
    expect(url).toMatch(/mode=zones-nv/);
    expect(url).toMatch(/shape=torusknot/);
    const state = await getState(page, 'fresnel-zones');
    const again = await open(browser, url.slice(url.indexOf('embed.html')));
    await widget(again, 'fresnel-zones');
    expect(await getState(again, 'fresnel-zones')).toEqual(state);
    expect([...page.errors, ...again.errors]).toEqual([]);
    await again.close();
  });

  it('bad URL values give a visible notice and keep a valid state', async () => {
    const page = await open(browser, 'embed.html?w=fresnel-zones&mode=banana&lightTheta=400&alpha=x');
    await widget(page, 'fresnel-zones');
    const notices = await page.$$eval('.notice', (els) => els.map((e) => e.textContent));
    expect(notices).toHaveLength(3);
    expect(notices.join(' ')).toMatch(/banana/);
    const s = await getState(page, 'fresnel-zones');
    expect([s.mode, s.lightTheta, s.alpha]).toEqual(['fresnel-nv', 180, 0.3]);
    expect(await distinctColors(page, await shot(page, CANVAS))).toBeGreaterThan(20);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('measures the analytic n·v zone shares of an orthographic sphere on the GPU', async () => {
    const page = await zonesIn({ mode: 'zones-nv', shape: 'sphere', camera: 'orthographic' });
    const shares = await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].getZoneShares());
    const analytic = sphereZoneFractions();
    console.log(
      `zone shares GPU ${shares.map((s) => (s * 100).toFixed(2)).join(' / ')} % vs analytic ` +
        `${analytic.map((s) => (s * 100).toFixed(2)).join(' / ')} %`,
    );
    shares.forEach((s, i) => expect(Math.abs(s - analytic[i])).toBeLessThan(0.003));
    expect(page.errors).toEqual([]);
  });

  it(
    'on an orthographic sphere, the weighted shares match a float64 quadrature over the ' +
      'same 64 lights (α 0.1: 4.0% red, α 0.3: 1.4%)',
    async () => {
      for (const [alpha, red] of [
        [0.1, 0.0405],
        [0.3, 0.0136],
      ]) {
        const expected = weightedSphereShares(alpha);
        expect(expected[2]).toBeCloseTo(red, 3); // the figures fresnel.html quotes
        const page = await zonesIn({ mode: 'zones-lh-weighted', shape: 'sphere', alpha });
        const avg = await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].getAverageShares());
        console.log(
          `weighted shares, sphere, α ${alpha}: GPU ${avg.map((x) => (x * 100).toFixed(2))} %, ` +
            `quadrature ${expected.map((x) => (x * 100).toFixed(2))} %`,
        );
        // a 128² image of the sphere
        avg.forEach((x, i) => expect(Math.abs(x - expected[i]), `zone ${i}`).toBeLessThan(0.003));
        expect(page.errors).toEqual([]);
      }
    },
  );

  it(
    'bears out the talk: weighted by the BRDF, over all light directions, ' + 'green predominates and red is rare',
    async () => {
      const page = await zonesIn({ mode: 'zones-lh-weighted', shape: 'torusknot' });
      const avg = await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].getAverageShares());
      console.log(
        `weighted l·h zone shares over 64 lights (torus knot, alpha 0.3): ` +
          `${avg.map((s) => (s * 100).toFixed(1)).join(' / ')} %`,
      );
      expect(avg[0]).toBeGreaterThan(0.5);
      expect(avg[2]).toBeLessThan(0.05);
      expect(avg.reduce((a, b) => a + b)).toBeCloseTo(1, 6);
      expect(page.errors).toEqual([]);
    },
  );

  it('compiles only the terms a mode uses, and reuses a variant when it comes back', async () => {
    const page = await zonesIn({ mode: 'zones-nv' });
    const info = () => page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].getProgramInfo());
    expect((await info()).fragmentShader).not.toMatch(/ndfGGX|visibilitySmith|fresnelDielectric/);
    await setControl(page, 'Mode', 'Zones of l·h × rest of BRDF');
    const weighted = await info();
    expect(weighted.fragmentShader).toMatch(/ndfGGX/);
    await setControl(page, 'Mode', 'Zones of n·v');
    await setControl(page, 'Mode', 'Zones of l·h × rest of BRDF');
    expect((await info()).variants).toBe(weighted.variants);
    expect(page.errors).toEqual([]);
  });

  it('moves the light with the keyboard and by dragging, and probes the surface', async () => {
    const page = await zonesIn({ mode: 'zones-lh', lightTheta: 60 });
    await page.focus(CANVAS);
    await page.keyboard.press('ArrowUp');
    expect((await getState(page, 'fresnel-zones')).lightTheta).toBe(55);
    const box = await (await page.$(CANVAS)).boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.up();
    expect((await getState(page, 'fresnel-zones')).lightTheta).toBeLessThan(1);
    await page.mouse.move(box.x + box.width / 2 + 20, box.y + box.height / 2 + 10);
    const probe = () => page.$eval('.probe', (el) => el.textContent);
    await expect.poll(probe, { timeout: WAIT_MS }).toMatch(/n·v.*n·l.*n·h.*l·h.*F\(n·v\) exact/s);
    expect(page.errors).toEqual([]);
  });

  it('the modes of n·v hide the light and leave it where it is; a drag does not move it', async () => {
    const page = await zonesIn({ mode: 'zones-nv', lightTheta: 60 });
    const sunShown = () => page.$eval('.light-overlay', (svg) => getComputedStyle(svg).display !== 'none');
    expect(await sunShown()).toBe(false);
    const box = await (await page.$(CANVAS)).boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.up();
    await page.focus(CANVAS);
    await page.keyboard.press('ArrowUp');
    expect((await getState(page, 'fresnel-zones')).lightTheta).toBe(60);
    await setControl(page, 'Mode', 'Zones of l·h');
    expect(await sunShown()).toBe(true);
    expect(page.errors).toEqual([]);
  });

  it('the probe follows the light: at the centre of the orthographic sphere n·l = cos θ, 60° then 65°', async () => {
    const page = await zonesIn({ mode: 'zones-lh', lightTheta: 60 });
    const box = await (await page.$(CANVAS)).boundingBox();
    await page.mouse.move(box.x + box.width / 2 + 10, box.y + box.height / 2); // a move, wherever a case left it
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    const nl = () =>
      page.$$eval('.probe tr', (trs) =>
        Number.parseFloat(trs.find((tr) => tr.cells[0].textContent === 'n·l').cells[1].textContent),
      );
    await expect.poll(nl, { timeout: WAIT_MS }).toBeCloseTo(Math.cos((60 * Math.PI) / 180), 3);
    await page.evaluate(() => globalThis.__shadingLab.widgets['fresnel-zones'].update({ lightTheta: 65 }));
    await expect.poll(nl, { timeout: WAIT_MS }).toBeCloseTo(Math.cos((65 * Math.PI) / 180), 3);
    expect(page.errors).toEqual([]);
  });

  it('the Fresnel picture outlines the zones of n·v at sin 45° and sin 75° of the sphere radius', async () => {
    const page = await zonesIn({ mode: 'fresnel-nv', shape: 'sphere', camera: 'orthographic' }); // the frame drawn
    // along the row through the centre, rightwards: the radius (in sphere radii) of the first yellow and red pixels
    const radii = await withPixels(
      page,
      await shot(page, CANVAS),
      `(image) => {
        const near = (i, [r, g, b]) => Math.abs(image.data[i] - r) + Math.abs(image.data[i + 1] - g) +
          Math.abs(image.data[i + 2] - b) < 60;
        const cy = Math.round(image.height / 2), cx = image.width / 2, R = image.height / 2 / 1.1;
        const first = (rgb) => {
          for (let x = Math.ceil(cx); x < image.width; x++)
            if (near((cy * image.width + x) * 4, rgb)) return (x - cx) / R;
          return null;
        };
        return [first([0xf5, 0xd3, 0x27]), first([0xe2, 0x35, 0x2b])];
      }`,
    );
    expect(Math.abs(radii[0] - Math.SQRT1_2)).toBeLessThan(0.02);
    expect(Math.abs(radii[1] - Math.sin((75 * Math.PI) / 180))).toBeLessThan(0.02);
    expect(page.errors).toEqual([]);
  });

  it('draws nothing while idle', async () => {
    const page = await keptChapter();
    await page.$eval('[data-slot="fresnel-zones"]', (el) => el.scrollIntoView());
    await untilIdle(page); // its first frames and its zone shares' read-back done: nothing more asked for
    const count = () => page.evaluate(() => [window.__drawCalls, globalThis.__shadingLab.frames]);
    const before = await count();
    // a window for what must not come, counted in the page's frames (60: a second at 60 Hz, longer when loaded)
    await afterFrames(page, 60);
    expect(before[0]).toBeGreaterThan(0);
    expect(await count()).toEqual(before);
    expect(await page.evaluate(() => globalThis.__shadingLab.pending), 'work asked for while idle').toBe(0);
  });

  it('follows the size of its frame', async () => {
    const page = await open(browser, 'embed.html?w=fresnel-zones', { width: 700, height: 700 });
    await widget(page, 'fresnel-zones');
    const w1 = await page.$eval(CANVAS, (c) => c.width);
    await page.setViewport({ width: 1200, height: 900 });
    await page
      .waitForFunction((w) => document.querySelector('.widget-fresnel-zones canvas').width > w * 1.2, {}, w1)
      .catch(() => {}); // a canvas that does not follow fails below, with its width
    const w2 = await page.$eval(CANVAS, (c) => c.width);
    expect(w1).toBeLessThanOrEqual(700);
    expect(w2).toBeGreaterThan(w1 * 1.2);
    await page.close();
  });
});

describe('fresnel-curves and f0-tables', () => {
  it('a checkbox adds curves, the URL keeps them, and bad materials are reported', async () => {
    const page = await open(browser, 'embed.html?w=fresnel-curves&materials=gold,unobtainium');
    await widget(page, 'fresnel-curves');
    expect(await page.$eval('.notice', (el) => el.textContent)).toMatch(/unobtainium/);
    const before = await shot(page, '.plot-canvas');
    await setControl(page, 'Silver', true);
    expect(await shot(page, '.plot-canvas')).not.toBe(before);
    expect(decodeURIComponent(page.url())).toMatch(/materials=gold,silver/);
    expect(await page.$$eval('.readout tbody tr', (rows) => rows.length)).toBe(6);
    // Save CSV hands the plotted data to a download: capture the blob instead of saving it
    const csv = await page.evaluate(async () => {
      let blob;
      URL.createObjectURL = (b) => ((blob = b), 'blob:captured');
      HTMLAnchorElement.prototype.click = () => {};
      [...document.querySelectorAll('.toolbar button')].find((b) => b.textContent === 'Save CSV').click();
      return blob.text();
    });
    const lines = csv.trim().split('\n');
    expect(lines[0]).toBe(
      '"Angle of incidence θ (degrees)","Gold R exact","Gold R Schlick","Gold G exact","Gold G ' +
        'Schlick","Gold B exact","Gold B Schlick","Silver R exact","Silver R Schlick","Silver G ' +
        'exact","Silver G Schlick","Silver B exact","Silver B Schlick"',
    );
    expect(lines).toHaveLength(362); // 0°..90° in 0.25° steps, plus the header
    expect(Number(lines[1].split(',')[1])).toBeCloseTo(0.999, 3); // gold R at 0°: the talk's 1.00, clamped
    expect(Number(lines[361].split(',')[1])).toBeCloseTo(1, 9); // grazing
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('a material picked in the tables loads into the other widgets of the chapter page', async () => {
    const page = await keptChapter();
    await widget(page, 'tables');
    await page.click('tr[data-material="diamond"] a[href*="w=fresnel-zones"]');
    // the page scrolls smoothly to the widget that took the material: the next click waits till it stops
    await page.evaluate(async () => {
      for (let still = 0, y = scrollY; still < 5;) {
        await new Promise((r) => requestAnimationFrame(r));
        [still, y] = scrollY === y ? [still + 1, y] : [0, scrollY];
      }
    });
    await page.click('tr[data-material="iron"] a[href*="w=fresnel-curves"]');
    await expect.poll(async () => (await getState(page, 'zones')).material, { timeout: WAIT_MS }).toBe('diamond');
    await expect.poll(async () => (await getState(page, 'curves')).materials, { timeout: WAIT_MS }).toContain('iron');
    await expect.poll(() => page.url(), { timeout: WAIT_MS }).toMatch(/zones\.material=diamond/);
    expect(page.errors).toEqual([]);
  });
});

describe('without WebGL2', () => {
  it('3-D views say so in words; the rest of the page works', async () => {
    // a browser without WebGL (Chromium's --disable-3d-apis, a blocklisted GPU) answers getContext('webgl2') with
    // null: the same, in this page alone, instead of a Chromium of its own launched with that flag
    const page = await open(browser, 'fresnel.html', {
      beforeLoad: (p) =>
        p.evaluateOnNewDocument(() => {
          for (const Canvas of [HTMLCanvasElement, OffscreenCanvas]) {
            const real = Canvas.prototype.getContext;
            Canvas.prototype.getContext = function getContext(type, ...rest) {
              return /webgl/i.test(type) ? null : real.call(this, type, ...rest);
            };
          }
        }),
    });
    await widget(page, 'tables');
    expect(await page.$eval('.widget-fresnel-zones .blocking-message', (el) => el.textContent)).toMatch(
      /needs WebGL2/,
    );
    expect(await page.$$eval('.widget-fresnel-curves .plot', (els) => els.length)).toBe(2);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
