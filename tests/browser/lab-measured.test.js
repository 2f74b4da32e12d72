// A measured BRDF in the material lab, in Chromium: a MERL file written in Node from GGX (α 0.2, f0 0.04,
// c_diff 0.3, the measured widget's synthetic plastic) is picked in the lab; its Monte Carlo reference over the
// tabulated BRDF (a 3-D texture) must be the picture of the same GGX material's analytic reference, in the white
// furnace and in the studio, within the Monte Carlo noise (4 standard errors) and 1 % (the table's interpolation);
// importance sampling of the fitted lobe must meet the same reference in the furnace, and in the studio stay as
// close to it as the analytic material's importance sampling does; the methods without a form for a table say so.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open, untilIdle } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';
import { writeMerl } from '../../src/measured/merl.js';
import { modelBRDF } from '../../src/measured/fit.js';
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
// The four references converged here are most of the file's time: each stops at the samples its comparisons need
// (sampleTarget's cap, src/core/framework/debug-hooks.js). The noise a comparison allows is measured from the
// pictures, so fewer samples only widen it: in the studio at 128 samples, differences of 0.001 to 0.024 against
// allowances of 0.017 to 0.059 (two runs), and importance sampling's error against the reference compared with the
// analytic material's at the same count. In the furnace importance sampling must come within 1 % of the reference,
// whose own noise counts in that figure: 0.6 to 0.7 % at 512 samples, 0.98 % at 256 (too close), so 512.
const SAMPLES = { furnace: 512, studio: 128 };

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
/**
 * Per point and channel of the reference image, the mean of the 5 × 5 texels around it and its standard error
 * (their spread / 5: Monte Carlo noise, and the picture's own variation there, which only makes it larger).
 */
const readReference = () =>
  page.evaluate(
    (list, res) => {
      const image = globalThis.__shadingLab.widgets.lab.read('reference');
      return list.map(([i, j]) =>
        [0, 1, 2].map((c) => {
          const x = [];
          for (let dj = -2; dj <= 2; dj++)
            for (let di = -2; di <= 2; di++) x.push(image[((j + dj) * res + i + di) * 4 + c]);
          const mean = x.reduce((a, b) => a + b) / 25;
          return { mean, se: Math.sqrt(x.reduce((a, b) => a + (b - mean) ** 2, 0) / 24 / 25) };
        }),
      );
    },
    POINTS.map(texelOf),
    RES,
  );
const setAndConverge = async (state) => {
  await page.evaluate(
    (s, cap) => {
      globalThis.__shadingLab.maxSamples = cap; // read by the lab's next frame (sampleTarget)
      globalThis.__shadingLab.widgets.lab.update(s);
    },
    state,
    SAMPLES[state.environment],
  );
  await untilIdle(page);
  await converged();
};

beforeAll(async () => {
  file = join(mkdtempSync(join(tmpdir(), 'merl-')), 'synthetic-ggx.binary');
  writeFileSync(file, new Uint8Array(writeMerl(modelBRDF('ggx', TRUTH))));
  browser = await launchBrowser();
  // the lab's images are 192 × 192 whatever the window: a small one spares SwiftShader the display's pixels
  page = await open(browser, `rendering.html?${QUERY}&lab.environment=furnace`, {
    ...SMALL_VIEWPORT,
    maxSamples: SAMPLES.furnace,
  });
  // in view (in a small window the chapter's opening words fill the first screen), and mounted; its reference
  // converges in the first test, within that test's time
  const lab = await page.waitForSelector('.widget-material-lab', { timeout: 120_000 });
  await lab.evaluate((el) => el.scrollIntoView());
  await page.waitForFunction(() => globalThis.__shadingLab?.widgets?.lab, { timeout: 120_000 });
}, 180_000);
afterAll(async () => {
  await browser?.close();
});

describe('material lab: a measured BRDF (a MERL file written from GGX) against the same GGX material', () => {
  const analytic = {};
  it('the analytic GGX material converges in the furnace and in the studio (the pictures to match)', async () => {
    await untilIdle(page);
    await converged();
    expect((await lab()).samples).toBe(SAMPLES.furnace);
    analytic.furnace = await readReference();
    analytic.furnaceStats = await lab();
    await setAndConverge({ environment: 'studio' });
    analytic.studio = await readReference();
    analytic.studioStats = await lab();
  }, 600_000);

  // picked in the studio, where the analytic material was last: the measured reference starts there, and the
  // comparisons below take the studio first, so that no reference is converged twice
  it('the picked file becomes the lab’s material, with its GGX fit (α 0.2 within 2 %) to sample by', async () => {
    const input = await page.$('.env-drop input[type=file]');
    await input.uploadFile(file);
    await page.waitForFunction(() => globalThis.__shadingLab.widgets.lab.getMeasured()?.fit, {
      timeout: 300_000,
      polling: 1000,
    });
    const measured = await page.evaluate(() => globalThis.__shadingLab.widgets.lab.getMeasured());
    expect(measured.name).toBe('synthetic-ggx.binary');
    expect(Math.abs(measured.fit.params.alpha / TRUTH.alpha - 1)).toBeLessThan(0.02);
    expect((await page.evaluate(() => globalThis.__shadingLab.widgets.lab.getState())).brdfSource).toBe('measured');
  }, 320_000);

  for (const environment of ['studio', 'furnace']) {
    it(
      `${environment}: the measured reference is the analytic GGX reference within 4 standard ` +
        `errors of the MC noise and 1 % (the table's interpolation)`,
      async () => {
        await setAndConverge({ environment });
        const measured = await readReference();
        const g = (p) => `${p[1].mean.toFixed(4)} ± ${p[1].se.toFixed(4)}`;
        console.log(
          `lab, measured vs analytic GGX, ${environment} (G): ` +
            measured.map((m, k) => `${g(m)} / ${g(analytic[environment][k])}`).join(', '),
        );
        measured.forEach((rgb, k) =>
          rgb.forEach((x, c) => {
            const want = analytic[environment][k][c];
            const noise = 4 * Math.hypot(x.se, want.se);
            expect(Math.abs(x.mean - want.mean), `point ${k}, channel ${c}`).toBeLessThan(noise + 0.01 * want.mean);
          }),
        );
        // importance sampling of the fitted lobe (256 + 256 samples) against the reference: one picture in the
        // furnace; in the studio (small bright lights the lobe rarely hits) no closer than the analytic material's
        // importance sampling gets (256 samples, the same pattern on every pixel): the method's error, not the table's
        const stats = await lab();
        const own = analytic[`${environment}Stats`].relative;
        console.log(
          `lab, ${environment}: importance vs reference, relative RMS: ` +
            `measured ${(100 * stats.relative).toFixed(2)} %, ` +
            `analytic GGX ${(100 * own).toFixed(2)} %`,
        );
        if (environment === 'furnace') expect(stats.relative).toBeLessThan(0.01);
        else expect(stats.relative).toBeLessThan(1.5 * own);
      },
      600_000,
    );
  }

  it('the split sum says it has no form for a table; no console errors', async () => {
    await page.evaluate(() => globalThis.__shadingLab.widgets.lab.update({ envMethod: 'split-sum' }));
    await untilIdle(page);
    const notes = await page.$eval('.lab-notes', (e) => e.textContent);
    expect(notes).toMatch(/Measured BRDF \(synthetic-ggx\.binary\): the reference integrates the table itself/);
    expect(notes).toMatch(/The split sum has no form for a table/);
    expect(page.errors).toEqual([]);
  }, 120_000);
});
