// The material lab with energy compensation, in Chromium: in the white furnace, with F = 1 and α = 1, a specular
// sphere compensated by Kulla–Conty or Turquin reflects everything it receives (albedo 1, the truth by
// construction of both), in the approximation (split sum) and in the Monte Carlo reference; uncompensated it
// does not (E = 1 − ln 2 head-on).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser, open, untilIdle } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';

const EXTENT = 1.1; // the lab's view half width (src/lab/lab-renderer.js)
const RES = 192; // the lab's image size (src/widgets/material-lab/material-lab.js)
const POINTS = [
  [0, 0],
  [0.5, 0],
  [-0.5, 0.5],
  [0, -0.8],
]; // sphere coordinates, n = (x, y, sqrt(1 - x² - y²))
const texelOf = ([x, y]) => [x, y].map((c) => Math.floor((c / (2 * EXTENT) + 0.5) * RES));

// the converged reference is the claim: 128 samples a pixel in software WebGL took over a minute under a load
// average of 26 (the wait for it below has WAIT_MS, within the project's test budget)

let browser;
let page;
// one page for the three: each test sets the compensation, which restarts the reference (a key of its own), and the
// lab's images are 192 × 192 whatever the window (a small one spares SwiftShader the display's pixels)
beforeAll(async () => {
  browser = await launchBrowser();
  const query =
    'lab.punctual=0&lab.environment=furnace&lab.layers=specular&lab.F=one&lab.alpha=1' +
    '&lab.compensation=kullaConty&lab.refSamples=128';
  page = await open(browser, `rendering.html?${query}`, SMALL_VIEWPORT);
  // in view (in a small window the chapter's opening words fill the first screen), and mounted; its reference
  // converges in the first test, within that test's time
  const lab = await page.waitForSelector('.widget-material-lab', { timeout: WAIT_MS });
  await lab.evaluate((el) => el.scrollIntoView());
  await page.waitForFunction(() => globalThis.__shadingLab?.widgets?.lab, { timeout: WAIT_MS });
});
afterAll(async () => {
  await browser?.close();
});

async function furnaceLab(compensation) {
  await page.evaluate((c) => globalThis.__shadingLab.widgets.lab.update({ compensation: c }), compensation);
  await untilIdle(page);
  await page.waitForFunction(
    () => {
      const p = globalThis.__shadingLab.widgets.lab.getProgress();
      return p.frame >= p.target;
    },
    { timeout: WAIT_MS },
  );
  // the red channel, averaged over the 5 × 5 texels around each point (the reference's noise, up to 3× larger
  // under Turquin's factor 1/E, averages down; the furnace is smooth there)
  const read = (which) =>
    page.evaluate(
      (which, list, res) => {
        const image = globalThis.__shadingLab.widgets.lab.read(which);
        return list.map(([i, j]) => {
          let sum = 0;
          for (let dj = -2; dj <= 2; dj++) for (let di = -2; di <= 2; di++) sum += image[((j + dj) * res + i + di) * 4];
          return sum / 25;
        });
      },
      which,
      POINTS.map(texelOf),
      RES,
    );
  return { approx: await read('approx'), reference: await read('reference') };
}

describe('material lab: multiple-scattering compensation in the white furnace', () => {
  for (const compensation of ['kullaConty', 'turquin']) {
    it(
      `${compensation}: albedo 1 in the split sum (within 1e-2) and in the ` + `converged reference (within 3e-2)`,
      async () => {
        const { approx, reference } = await furnaceLab(compensation);
        console.log(
          `lab furnace, ${compensation}: approximation ${approx.map((x) => x.toFixed(4)).join(', ')}; ` +
            `reference ${reference.map((x) => x.toFixed(4)).join(', ')}`,
        );
        for (const x of approx) expect(Math.abs(x - 1)).toBeLessThan(1e-2);
        for (const x of reference) expect(Math.abs(x - 1)).toBeLessThan(3e-2);
        expect(page.errors).toEqual([]);
      },
    );
  }

  it('none: the sphere stays below 1 (E = 1 − ln 2 = 0.307 head-on, in both images)', async () => {
    const { approx, reference } = await furnaceLab('none');
    expect(Math.abs(approx[0] - (1 - Math.LN2))).toBeLessThan(1e-2);
    expect(Math.abs(reference[0] - (1 - Math.LN2))).toBeLessThan(3e-2);
    expect(page.errors).toEqual([]);
  });
});
