// A measured BRDF in the material lab, in Chromium: a MERL file written in Node from GGX (α 0.2, f0 0.04,
// c_diff 0.3, the measured widget's synthetic plastic) is picked in the lab. In the studio its Monte Carlo reference
// over the tabulated BRDF (a 3-D texture) must be the picture of the same GGX material's analytic reference, within
// the Monte Carlo noise (4 standard errors) and 1 % (the table's interpolation), and importance sampling of the
// fitted lobe must come as close to it as the analytic material's importance sampling does. In the white furnace the
// reference must be the material's directional albedo, c_diff + f0 A(μ) + B(μ) by the split sum's quadrature in Node
// (dfgSplitSum, src/math/integrate.js), within 4 standard errors and 1 %, and importance sampling must come within
// 1 % of the reference. The methods without a form for a table say so.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser, open, untilIdle } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';
import { writeMerl } from '../../src/measured/merl.js';
import { modelBRDF } from '../../src/measured/fit.js';
import { dfgSplitSum } from '../../src/math/integrate.js';
import { EXAMPLES } from '../../src/widgets/measured-brdf/model.js';

const EXTENT = 1.1; // the lab's view half width (src/lab/lab-renderer.js)
const RES = 192; // the lab's image size (src/widgets/material-lab/material-lab.js)
const POINTS = [
  [0, 0],
  [0.5, 0],
  [-0.5, 0.5],
  [0, -0.8],
  [0.7, 0.6],
]; // sphere coordinates
const texelOf = ([x, y]) => [x, y].map((c) => Math.floor((c / (2 * EXTENT) + 0.5) * RES));
const TRUTH = EXAMPLES.ggx.params; // α 0.2, f0 0.04, c_diff 0.3
// c_diff 0.3 linear as the lab's sRGB colour field takes it: 0.3005 back in linear (0.2 % off, far below the noise)
const QUERY =
  'lab.punctual=0&lab.alpha=0.2&lab.f0=0.04&lab.cdiff=959595&lab.envMethod=importance&lab.samples=256' +
  '&lab.refSamples=512';
// The references converged here, and the importance-sampled pictures (256 + 256 samples a pixel), are most of the
// file's time: each reference stops at the samples its comparisons need (sampleTarget's cap,
// src/core/framework/debug-hooks.js), and the lab is out of sight while the fit runs. The noise a comparison allows
// is measured from the pictures, so fewer samples only widen it: in the studio at 128 samples, differences of 0.001 to
// 0.024 against allowances of 0.017 to 0.059 (two runs), and importance sampling's error against the reference
// compared with the analytic material's at the same count. In the furnace the reference is compared with the
// albedo, which has no noise, at 64 samples (differences of 0.0001 to 0.0026 against allowances of 0.005 to 0.009,
// two runs); importance sampling's error is taken against the reference averaged over the texels of equal n·v, 8
// of them, whose noise is that of 512 samples (0.6 to 0.7 %, which counts in that figure: 0.48 and 0.65 %, two runs).
const SAMPLES = { furnace: 64, studio: 128 };

/**
 * The GGX material's directional albedo at n·v = mu, per channel: what the furnace's picture converges to (12 nodes a
 * piece: within 3e-6 of the adaptive rule).
 */
const albedo = (mu) => {
  const [scale, bias] = dfgSplitSum(mu, TRUTH.alpha, {}, { nodes: 12 });
  return TRUTH.cdiff.map((c, k) => c + TRUTH.f0[k] * scale + bias);
};
/** The albedo at texel (i, j)'s centre (orthographic, v = z: n·v is the sphere's height there), or null off it. */
const albedoAt = (() => {
  const seen = new Map();
  const coord = (i) => Math.abs((2 * (i + 0.5)) / RES - 1) * EXTENT;
  return (i, j) => {
    const [x, y] = [coord(i), coord(j)].sort((a, b) => a - b); // the furnace's picture is round
    const r2 = x * x + y * y;
    if (r2 >= 1) return null;
    const key = `${x} ${y}`;
    if (!seen.has(key)) seen.set(key, albedo(Math.sqrt(1 - r2)));
    return seen.get(key);
  };
})();

let browser;
let page;
let file;
const lab = () => page.evaluate(() => globalThis.__shadingLab.widgets.lab.getStats());
const converged = () =>
  page.waitForFunction(
    () => {
      const p = globalThis.__shadingLab.widgets.lab.getProgress();
      return p.frame >= p.target;
    },
    { timeout: 300_000, polling: 500 },
  );
/** One of the lab's images ('reference' or 'approx'), RGBA per texel, rows from the bottom. */
const readImage = (which) => page.evaluate((w) => Array.from(globalThis.__shadingLab.widgets.lab.read(w)), which);
/** Channel c of texel (i, j) of an image readImage gave. */
const texel = (image) => (i, j, c) => image[(j * RES + i) * 4 + c];
/**
 * Per point and channel of a picture (`value`: texel i, j, channel c → number), the mean of the 5 × 5 texels around
 * the point and its standard error (their spread / 5: Monte Carlo noise, and whatever variation of the picture is
 * left there, which only makes it larger).
 */
const patches = (value) =>
  POINTS.map(texelOf).map(([i, j]) =>
    [0, 1, 2].map((c) => {
      const x = [];
      for (let dj = -2; dj <= 2; dj++) for (let di = -2; di <= 2; di++) x.push(value(i + di, j + dj, c));
      const mean = x.reduce((a, b) => a + b) / 25;
      return { mean, se: Math.sqrt(x.reduce((a, b) => a + (b - mean) ** 2, 0) / 24 / 25) };
    }),
  );
/**
 * `image` against `truth` (texel i, j → RGB) over the sphere: relative RMS, the lab's own measure
 * (lab-error.frag.glsl).
 */
const relativeRms = (image, truth) => {
  let [squares, reference] = [0, 0];
  for (let j = 0; j < RES; j++)
    for (let i = 0; i < RES; i++) {
      if (!albedoAt(i, j) || image[(j * RES + i) * 4 + 3] <= 0.5) continue;
      const want = truth(i, j);
      for (let c = 0; c < 3; c++) {
        squares += (image[(j * RES + i) * 4 + c] - want[c]) ** 2;
        reference += want[c] ** 2;
      }
    }
  return Math.sqrt(squares / reference);
};
/**
 * The furnace's reference averaged over the texels at the same distance from the sphere's centre: an isotropic
 * BRDF under an even light sends the same radiance there (it depends on n·v alone), and each texel's samples are
 * its own, so the 8 such texels (4 on a diagonal) average to the noise of 8 times the samples.
 */
const roundAverage = (image) => {
  const key = (i, j) => [Math.abs(2 * i + 1 - RES), Math.abs(2 * j + 1 - RES)].sort((a, b) => a - b).join(' ');
  const sums = new Map();
  for (let j = 0; j < RES; j++)
    for (let i = 0; i < RES; i++) {
      if (!albedoAt(i, j)) continue;
      const sum = sums.get(key(i, j)) ?? sums.set(key(i, j), [0, 0, 0, 0]).get(key(i, j));
      for (let c = 0; c < 3; c++) sum[c] += image[(j * RES + i) * 4 + c];
      sum[3]++;
    }
  return (i, j) => {
    const sum = sums.get(key(i, j));
    return sum.slice(0, 3).map((x) => x / sum[3]);
  };
};
/** Caps the samples (read by the lab's next frame, sampleTarget), updates the state and waits for the reference. */
const setAndConverge = async (state) => {
  await page.evaluate(
    (s, cap) => {
      globalThis.__shadingLab.maxSamples = cap;
      globalThis.__shadingLab.widgets.lab.update(s);
    },
    state,
    SAMPLES[state.environment],
  );
  await untilIdle(page);
  await converged();
};

beforeAll(async () => {
  browser = await launchBrowser();
  // the lab's images are 192 × 192 whatever the window: a small one spares SwiftShader the display's pixels
  page = await open(browser, `rendering.html?${QUERY}&lab.environment=studio`, {
    ...SMALL_VIEWPORT,
    maxSamples: SAMPLES.studio,
  });
  // in view (in a small window the chapter's opening words fill the first screen), and mounted; its reference
  // converges in the first test, within that test's time
  const lab = await page.waitForSelector('.widget-material-lab', { timeout: WAIT_MS });
  await lab.evaluate((el) => el.scrollIntoView());
  await page.waitForFunction(() => globalThis.__shadingLab?.widgets?.lab, { timeout: WAIT_MS });
  // written while Chromium draws the lab's first reference (seconds of Node's time; the page's work is its own)
  file = join(mkdtempSync(join(tmpdir(), 'merl-')), 'synthetic-ggx.binary');
  writeFileSync(file, new Uint8Array(writeMerl(modelBRDF('ggx', TRUTH))));
});
afterAll(async () => {
  await browser?.close();
});

describe('material lab: a measured BRDF (a MERL file written from GGX) against the same GGX material', () => {
  const analytic = {};
  it('the analytic GGX material converges in the studio (the picture to match)', async () => {
    await untilIdle(page);
    await converged();
    expect((await lab()).samples).toBe(SAMPLES.studio);
    analytic.studio = patches(texel(await readImage('reference')));
    analytic.studioStats = await lab();
  }, 600_000);

  // picked with the lab out of sight (it draws only when seen): until the fit is in, the table would be drawn by the
  // state's lobe, and drawn again when the fit's α comes, while the fit's worker wants the same cores
  it('the picked file becomes the lab’s material, with its GGX fit (α 0.2 within 2 %) to sample by', async () => {
    const input = await page.$('.env-drop input[type=file]');
    await page.evaluate(() => window.scrollTo(0, 0));
    await input.uploadFile(file);
    await page.waitForFunction(() => globalThis.__shadingLab.widgets.lab.getMeasured(), {
      timeout: 300_000,
      polling: 500,
    });
    await page.waitForFunction(() => globalThis.__shadingLab.widgets.lab.getMeasured()?.fit, {
      timeout: 300_000,
      polling: 1000,
    });
    // back in sight: drawn with the table and its fit (the notes name the table from its first frame), in the studio,
    // where the next test compares it
    await page.$eval('.widget-material-lab', (el) => el.scrollIntoView());
    await page.waitForFunction(() => document.querySelector('.lab-notes')?.textContent.includes('synthetic-ggx'), {
      timeout: WAIT_MS,
      polling: 200,
    });
    const measured = await page.evaluate(() => globalThis.__shadingLab.widgets.lab.getMeasured());
    expect(measured.name).toBe('synthetic-ggx.binary');
    expect(Math.abs(measured.fit.params.alpha / TRUTH.alpha - 1)).toBeLessThan(0.02);
    expect((await page.evaluate(() => globalThis.__shadingLab.widgets.lab.getState())).brdfSource).toBe('measured');
  }, 320_000);

  it(
    'studio: the measured reference is the analytic GGX reference within 4 standard errors of the MC noise ' +
      'and 1 % (the table’s interpolation); importance sampling as close to it as the analytic material’s',
    async () => {
      await setAndConverge({ environment: 'studio' });
      const measured = patches(texel(await readImage('reference')));
      const g = (p) => `${p[1].mean.toFixed(4)} ± ${p[1].se.toFixed(4)}`;
      console.log(
        'lab, measured vs analytic GGX, studio (G): ' +
          measured.map((m, k) => `${g(m)} / ${g(analytic.studio[k])}`).join(', '),
      );
      measured.forEach((rgb, k) =>
        rgb.forEach((x, c) => {
          const want = analytic.studio[k][c];
          const noise = 4 * Math.hypot(x.se, want.se);
          expect(Math.abs(x.mean - want.mean), `point ${k}, channel ${c}`).toBeLessThan(noise + 0.01 * want.mean);
        }),
      );
      // in the studio (small bright lights the lobe rarely hits) importance sampling gets no closer than the analytic
      // material's (256 samples, the same pattern on every pixel): the method's error, not the table's
      const stats = await lab();
      const own = analytic.studioStats.relative;
      console.log(
        'lab, studio: importance vs reference, relative RMS: ' +
          `measured ${(100 * stats.relative).toFixed(2)} %, analytic GGX ${(100 * own).toFixed(2)} %`,
      );
      expect(stats.relative).toBeLessThan(1.5 * own);
    },
    600_000,
  );

  it(
    'furnace: the measured reference is the directional albedo (the split sum’s quadrature in Node) within 4 ' +
      'standard errors of the MC noise and 1 % (the table’s interpolation); importance sampling within 1 % of it',
    async () => {
      await setAndConverge({ environment: 'furnace' });
      expect((await lab()).samples).toBe(SAMPLES.furnace);
      // the albedo taken off texel by texel: what is left is the reference's noise and the table's error
      const image = await readImage('reference');
      const reference = texel(image);
      const residual = patches((i, j, c) => reference(i, j, c) - albedoAt(i, j)[c]);
      const want = patches((i, j, c) => albedoAt(i, j)[c]);
      console.log(
        'lab, measured reference − albedo, furnace (G): ' +
          residual
            .map((p, k) => `${p[1].mean.toFixed(4)} ± ${p[1].se.toFixed(4)} of ${want[k][1].mean.toFixed(4)}`)
            .join(', '),
      );
      residual.forEach((rgb, k) =>
        rgb.forEach((x, c) => {
          const allowed = 4 * x.se + 0.01 * want[k][c].mean;
          expect(Math.abs(x.mean), `point ${k}, channel ${c}`).toBeLessThan(allowed);
        }),
      );
      // importance sampling of the fitted lobe (256 + 256 samples): one picture, its whole sphere against the
      // reference (whose noise at 8 × 64 samples, 0.6 to 0.7 %, counts in the figure) and, for the record, against
      // the albedo of GGX itself (the table departs from it at grazing view, in the sphere's outermost texels, n·v
      // below 0.05, in both pictures alike: 19 % RMS there, 0.3 % at most elsewhere)
      const approx = await readImage('approx');
      const error = relativeRms(approx, roundAverage(image));
      console.log(
        'lab, furnace: importance, relative RMS: ' +
          `against the reference ${(100 * error).toFixed(2)} %, against the albedo ` +
          `${(100 * relativeRms(approx, albedoAt)).toFixed(2)} %`,
      );
      expect(error).toBeLessThan(0.01);
    },
    600_000,
  );

  it('the split sum says it has no form for a table; no console errors', async () => {
    await page.evaluate(() => globalThis.__shadingLab.widgets.lab.update({ envMethod: 'split-sum' }));
    await untilIdle(page);
    const notes = await page.$eval('.lab-notes', (e) => e.textContent);
    expect(notes).toMatch(/Measured BRDF \(synthetic-ggx\.binary\): the reference integrates the table itself/);
    expect(notes).toMatch(/The split sum has no form for a table/);
    expect(page.errors).toEqual([]);
  });
});
