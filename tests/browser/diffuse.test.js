// The diffuse chapter in a real Chromium: the rendered spheres read back and compared with src/math, the plots'
// data against the JS terms, the URL state.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  getState,
  launchBrowser,
  open,
  pointUntil,
  setControl,
  shot,
  untilIdle,
  widget,
  withPixels,
} from './helpers.js';
import {
  diffuseFresnelWeighted,
  diffuseLambert,
  diffuseOrenNayar,
  diffuseOrenNayarQualitative,
} from '../../src/math/diffuse.js';
import { fresnelSchlick } from '../../src/math/fresnel.js';
import { linearToSrgb } from '../../src/math/color.js';
import { DEG } from '../../src/math/angles.js';

const BACKGROUND = 0x16; // the sphere grid's background, #16181d

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** The sphere canvas's red channel (the spheres are grey) as { width, height, at(x, y) }. */
async function readSpheres(page) {
  // a screenshot includes the labels drawn over the spheres
  await page.addStyleTag({ content: '.sphere-labels { display: none; }' });
  const png = await shot(page, '.sphere-grid canvas');
  const { width, height, red } = await withPixels(page, png, (image) => ({
    width: image.width,
    height: image.height,
    red: Array.from(image.data.filter((_, i) => i % 4 === 0)),
  }));
  return { width, height, at: (x, y) => red[y * width + x] };
}

/**
 * Finds the disc of sphere `i` of `n` by its silhouette on the middle row and column: centre and radius in
 * pixels (the sphere is drawn black where unlit, the background is #16181d, so both edges show).
 */
function findDisc(img, i, n) {
  const [x0, x1] = [Math.round((i * img.width) / n), Math.round(((i + 1) * img.width) / n)];
  const y = Math.floor(img.height / 2);
  const on = (x, yy) => Math.abs(img.at(x, yy) - BACKGROUND) > 8;
  let left = x0;
  while (left < x1 && !on(left, y)) left++;
  let right = x1 - 1;
  while (right > left && !on(right, y)) right--;
  const cx = (left + right + 1) / 2;
  let top = 0;
  while (top < img.height && !on(Math.floor(cx), top)) top++;
  let bottom = img.height - 1;
  while (bottom > top && !on(Math.floor(cx), bottom)) bottom--;
  return { cx, cy: (top + bottom + 1) / 2, r: (right - left + 1 + bottom - top + 1) / 4 };
}

/** Pixel of the disc at sphere coordinates (x right, y up), and the normal there, from that pixel's centre. */
function pixelAt(disc, x, y) {
  const px = Math.round(disc.cx + x * disc.r - 0.5);
  const py = Math.round(disc.cy - y * disc.r - 0.5);
  const nx = (px + 0.5 - disc.cx) / disc.r;
  const ny = -(py + 0.5 - disc.cy) / disc.r;
  return { px, py, n: [nx, ny, Math.sqrt(Math.max(1 - nx * nx - ny * ny, 0))] };
}

const to8bit = (radiance) => Math.round(linearToSrgb(Math.min(Math.max(radiance, 0), 1)) * 255);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const lightFrom = (theta, phi) => [
  Math.sin(theta * DEG) * Math.cos(phi * DEG),
  Math.sin(theta * DEG) * Math.sin(phi * DEG),
  Math.cos(theta * DEG),
];
/** cos of the azimuth between l and v about n, from their tangent-plane parts (written out here, not imported). */
function azimuthCos(n, l, v) {
  const lt = [0, 1, 2].map((k) => l[k] - dot(n, l) * n[k]);
  const vt = [0, 1, 2].map((k) => v[k] - dot(n, v) * n[k]);
  const d = Math.sqrt(dot(lt, lt) * dot(vt, vt));
  return d > 1e-6 ? dot(lt, vt) / d : 1;
}
// sample points on the disc, away from the silhouette (where a pixel spans a wide range of normals)
const SAMPLES = [
  [0, 0],
  [0.3, 0.1],
  [-0.4, 0.3],
  [0.6, -0.2],
  [-0.5, -0.5],
  [0.1, 0.75],
  [0.8, 0.1],
  [-0.82, 0.05],
];

describe('diffuse chapter page', () => {
  it('loads cleanly with every model drawn and the plots filled', async () => {
    const page = await open(browser, 'diffuse.html');
    await widget(page, 'diffuse');
    const plots = await page.evaluate(() => globalThis.__shadingLab.widgets.diffuse.getPlots());
    expect(plots.profile).toHaveLength(6);
    expect(plots.tradeOff).toHaveLength(8); // x, five models, F alone, the line at 1
    const img = await readSpheres(page);
    for (let i = 0; i < 5; i++) expect(findDisc(img, i, 5).r).toBeGreaterThan(20);
    // the probe at the centre of the fourth sphere (full Oren–Nayar; defaults sigma 40°, c 0.8, light at the viewer)
    const ratio = diffuseOrenNayar(1, 1, 1, 40 * DEG, 0.8) / diffuseLambert(0.8);
    const probe = () => page.$eval('.widget-diffuse-explorer .probe', (el) => el.textContent);
    await pointUntil(page, '.sphere-grid canvas', [0.7, 0.5], async () =>
      (await probe()).includes(`f / Lambert${ratio.toFixed(4)}`),
    );
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('diffuse-explorer spheres, read back from the canvas', () => {
  const W = { width: 900, height: 800 };

  it('at sigma = 0 the Oren–Nayar spheres equal the Lambert sphere, pixel for pixel', async () => {
    // one sphere at a time in the same cell, so every model is rasterised at exactly the same pixels
    const page = await open(
      browser,
      'embed.html?w=diffuse-explorer&diffuse=lambert&sigma=0&lightTheta=50&lightPhi=30',
      W,
    );
    await widget(page, 'diffuse-explorer');
    const lambert = await readSpheres(page);
    const disc = findDisc(lambert, 0, 1);
    for (const model of ['orenNayar', 'orenNayarQualitative']) {
      await page.evaluate((m) => globalThis.__shadingLab.widgets['diffuse-explorer'].update({ diffuse: [m] }), model);
      await untilIdle(page);
      const img = await readSpheres(page);
      expect([img.width, img.height]).toEqual([lambert.width, lambert.height]);
      let [worst, lit] = [0, 0];
      for (let y = 0; y < img.height; y++) {
        for (let x = 0; x < img.width; x++) {
          worst = Math.max(worst, Math.abs(img.at(x, y) - lambert.at(x, y)));
          if (Math.hypot(x + 0.5 - disc.cx, y + 0.5 - disc.cy) < disc.r && lambert.at(x, y) > 40) lit++;
        }
      }
      console.log(
        `sigma = 0, ${model}: ${img.width}×${img.height} pixels (${lit} lit), ` +
          `worst |difference from Lambert| = ${worst}/255`,
      );
      expect(lit).toBeGreaterThan(10_000);
      expect(worst).toBeLessThanOrEqual(1);
    }
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('the Lambert sphere follows c·max(n·l, 0) across the disc', async () => {
    const [theta, phi, c] = [40, 20, 0.8];
    const page = await open(
      browser,
      `embed.html?w=diffuse-explorer&diffuse=lambert&lightTheta=${theta}&lightPhi=${phi}&cdiff=${c}`,
      W,
    );
    await widget(page, 'diffuse-explorer');
    const img = await readSpheres(page);
    const disc = findDisc(img, 0, 1);
    const l = lightFrom(theta, phi);
    const rows = SAMPLES.map(([x, y]) => {
      const { px, py, n } = pixelAt(disc, x, y);
      return { got: img.at(px, py), want: to8bit(Math.PI * diffuseLambert(c) * Math.max(dot(n, l), 0)) };
    });
    console.log(`Lambert sphere (8-bit), rendered vs c·max(n·l,0): ${rows.map((r) => `${r.got}/${r.want}`).join(' ')}`);
    for (const r of rows) expect(Math.abs(r.got - r.want)).toBeLessThanOrEqual(2);
    expect(new Set(rows.map((r) => r.want)).size).toBeGreaterThan(5); // the samples span the shading
    await page.close();
  });

  it('at high sigma with the light at the viewer, Oren–Nayar shows the full-moon flattening', async () => {
    const [sigma, c] = [60, 0.8];
    const page = await open(
      browser,
      'embed.html?w=diffuse-explorer&diffuse=lambert,orenNayar,orenNayarQualitative' +
        `&sigma=${sigma}&lightTheta=0&cdiff=${c}`,
      W,
    );
    await widget(page, 'diffuse-explorer');
    const img = await readSpheres(page);
    const [lam, on, onq] = [0, 1, 2].map((i) => findDisc(img, i, 3));
    const v = [0, 0, 1];
    const models = [
      [on, (n) => diffuseOrenNayar(n[2], n[2], azimuthCos(n, v, v), sigma * DEG, c)],
      [onq, (n) => diffuseOrenNayarQualitative(n[2], n[2], azimuthCos(n, v, v), sigma * DEG, c)],
    ];
    for (const [disc, f] of models) {
      for (const [x, y] of SAMPLES) {
        const { px, py, n } = pixelAt(disc, x, y);
        expect(Math.abs(img.at(px, py) - to8bit(Math.PI * f(n) * n[2]))).toBeLessThanOrEqual(2);
      }
    }
    // rim (85% of the radius) to centre, in linear radiance read back from the pixels
    const linear = (v8) => Math.pow((v8 / 255 + 0.055) / 1.055, 2.4);
    const ratio = (disc) =>
      linear(img.at(pixelAt(disc, 0.85, 0).px, pixelAt(disc, 0.85, 0).py)) /
      linear(img.at(pixelAt(disc, 0, 0).px, pixelAt(disc, 0, 0).py));
    const [rl, ro, rq] = [ratio(lam), ratio(on), ratio(onq)];
    const expected = (f) => (f([0.85, 0, Math.sqrt(1 - 0.85 ** 2)]) * Math.sqrt(1 - 0.85 ** 2)) / f([0, 0, 1]);
    console.log(
      `rim/centre at 0.85 R, sigma ${sigma}°: Lambert ${rl.toFixed(3)}, ` +
        `Oren–Nayar ${ro.toFixed(3)} (JS ${expected(models[0][1]).toFixed(3)}), ` +
        `qualitative ${rq.toFixed(3)} (JS ${expected(models[1][1]).toFixed(3)})`,
    );
    expect(rl).toBeCloseTo(Math.sqrt(1 - 0.85 ** 2), 1);
    expect(ro).toBeGreaterThan(rl + 0.3);
    expect(ro).toBeCloseTo(expected(models[0][1]), 1);
    expect(rq).toBeCloseTo(expected(models[1][1]), 1);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('diffuse-explorer plots and state', () => {
  it('plot data equal the JS terms', async () => {
    const s = { sigma: 35, cdiff: 0.7, f0: 0.08, lightTheta: 30, lightPhi: 60, viewTheta: 40 };
    const query = Object.entries(s)
      .map(([k, v]) => `${k}=${v}`)
      .join('&');
    const chosen = 'diffuse=lambert,fresnelWeighted,orenNayar';
    const page = await open(browser, `embed.html?w=diffuse-explorer&${chosen}&${query}`);
    await widget(page, 'diffuse-explorer');
    const plots = await page.evaluate(() => globalThis.__shadingLab.widgets['diffuse-explorer'].getPlots());
    const l = lightFrom(s.lightTheta, s.lightPhi);
    const v = [0, 0, 1];
    const p = (f, n, ll, vv) => Math.PI * f(dot(n, ll), dot(n, vv), azimuthCos(n, ll, vv)) * Math.max(dot(n, ll), 0);
    const terms = [
      (nl, nv) => (nl > 0 && nv > 0 ? diffuseLambert(s.cdiff) : 0),
      (nl, nv) => diffuseFresnelWeighted(nl, nv, s.f0, s.cdiff),
      (nl, nv, cp) => diffuseOrenNayar(nl, nv, cp, s.sigma * DEG, s.cdiff),
    ];
    // profile: along the diameter at the light's azimuth
    const [xs, ...profile] = plots.profile;
    expect(xs).toHaveLength(201);
    xs.forEach((x, i) => {
      const n = [x * Math.cos(s.lightPhi * DEG), x * Math.sin(s.lightPhi * DEG), Math.sqrt(Math.max(1 - x * x, 0))];
      terms.forEach((f, k) => expect(profile[k][i]).toBeCloseTo(p(f, n, l, v), 10));
    });
    // light sweep: flat patch, view at viewTheta, light in the plane of n and v
    const [angles, ...sweep] = plots.sweep;
    const vs = [Math.sin(s.viewTheta * DEG), 0, Math.cos(s.viewTheta * DEG)];
    angles.forEach((deg, i) => {
      const ls = [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
      terms.forEach((f, k) => expect(sweep[k][i]).toBeCloseTo(p(f, [0, 0, 1], ls, vs), 10));
    });
    // trade-off: Lambert's albedo is c, the Fresnel-weighted one c (1 - F(nv)) (1 - f0) 20/21 (Schlick)
    const [views, lambertTotal, fwTotal, , specular] = plots.tradeOff;
    views.forEach((deg, i) => {
      const F = fresnelSchlick(s.f0, Math.cos(deg * DEG));
      expect(specular[i]).toBeCloseTo(F, 12);
      expect(lambertTotal[i]).toBeCloseTo(F + s.cdiff, 10);
      expect(fwTotal[i]).toBeCloseTo(F + s.cdiff * (1 - F) * (1 - s.f0) * (20 / 21), 3);
    });
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it(
    'round-trips through the URL under its prefix; bad values give notices; ' + 'the light pad takes the keyboard',
    async () => {
      const page = await open(
        browser,
        'diffuse.html?diffuse.sigma=55&diffuse.diffuse=lambert,orenNayar&diffuse.cdiff=banana',
      );
      await widget(page, 'diffuse');
      const state = await getState(page, 'diffuse');
      expect([state.sigma, state.diffuse, state.cdiff]).toEqual([55, ['lambert', 'orenNayar'], 0.8]);
      expect(await page.$eval('.notice', (el) => el.textContent)).toMatch(/banana/);
      await setControl(page, 'Light from view (°)', 20);
      await page.focus('.light-pad canvas');
      await page.keyboard.press('ArrowDown');
      await untilIdle(page);
      expect((await getState(page, 'diffuse')).lightTheta).toBe(25);
      const url = page.url();
      expect(url).toMatch(/diffuse\.lightTheta=25/);
      const again = await open(browser, url.slice(url.indexOf('diffuse.html')));
      await widget(again, 'diffuse');
      expect(await getState(again, 'diffuse')).toEqual(await getState(page, 'diffuse'));
      expect(again.errors).toEqual([]);
      expect(page.errors).toEqual([]);
      await Promise.all([page.close(), again.close()]);
    },
  );
});
