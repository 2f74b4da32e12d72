// The measured-BRDF widget on the BRDF page in a real Chromium: a synthetic MERL file written in Node from
// ABC (so the right answer is known) is picked, parsed and fitted in the worker; the lobe, spheres, NDF slice
// and fit table show it; a fit goes into brdf-lobe, and into ndf-explorer with the measured NDF slice; a bad file
// is refused and the last good one kept.
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  getState,
  launchBrowser,
  open,
  pageOpenedBy,
  shot,
  untilIdle,
  widget,
  withPixels,
} from './helpers.js';
import { parseMerl, writeMerl } from '../../src/measured/merl.js';
import { modelBRDF } from '../../src/measured/fit.js';
import { EXAMPLES, THETA_H_DEG, measuredNdfSlice } from '../../src/widgets/measured-brdf/model.js';
import { ndfABC } from '../../src/math/ndf.js';
import { ndfHalfWidthDeg } from '../../src/math/ndf-width.js';

const TRUTH = EXAMPLES.abc.params; // a1 40, a2 2.5, f0 (0.9, 0.6, 0.3), c_diff (0.05, 0.1, 0.2)
let browser;
let page;
let file;

const fits = () => page.evaluate(() => globalThis.__shadingLab.widgets.measured.getFits());
const waitForFits = () =>
  page.waitForFunction(() => Object.keys(globalThis.__shadingLab.widgets.measured.getFits()).length === 5, {
    timeout: 600_000,
    polling: 1000,
  });

beforeAll(async () => {
  file = join(mkdtempSync(join(tmpdir(), 'merl-')), 'synthetic-abc.binary');
  writeFileSync(file, new Uint8Array(writeMerl(modelBRDF('abc', TRUTH))));
  browser = await launchBrowser();
  page = await open(browser, 'brdf.html#measured');
  await widget(page, 'measured');
  await widget(page, 'lobe');
});
afterAll(async () => {
  await browser?.close();
});

describe('a synthetic MERL file picked on the BRDF page', () => {
  it('is parsed in the worker and named as the source', async () => {
    const input = await page.$('.widget-measured-brdf input[type=file]');
    await input.uploadFile(file);
    await page.waitForFunction(
      () => document.querySelector('.measured-source')?.textContent.includes('synthetic-abc.binary'),
      { timeout: WAIT_MS, polling: 500 },
    );
    expect(await page.$eval('.measured-source', (e) => e.textContent)).toMatch(
      /346,568 of 1,458,000 nodes per channel missing/,
    );
  });

  it(
    'the five fits come back; the ABC fit has the parameters the file was written ' +
      'with (within 2 %) and the smallest error',
    async () => {
      await waitForFits();
      const f = await fits();
      const ranked = Object.values(f).sort((a, b) => a.error - b.error);
      expect(ranked[0].model).toBe('abc');
      expect(Math.abs(f.abc.params.a1 / TRUTH.a1 - 1)).toBeLessThan(0.02);
      expect(Math.abs(f.abc.params.a2 / TRUTH.a2 - 1)).toBeLessThan(0.02);
      f.abc.params.f0.forEach((x, c) => expect(Math.abs(x / TRUTH.f0[c] - 1)).toBeLessThan(0.02));
      const rows = await page.$$eval('.measured-fits tbody tr', (trs) => trs.map((tr) => tr.textContent));
      expect(rows).toHaveLength(5);
      expect(rows.find((r) => r.startsWith('ABC'))).toMatch(/ABC \(best\)a1 40\.0\d, a2 2\.50\d/);
    },
    620_000,
  );

  it('the lobe plot shows the three measured channels and the overlaid fit', async () => {
    await untilIdle(page);
    const label = await page.$$eval('.widget-measured-brdf figure.plot', (figs) =>
      figs.map((f) => f.querySelector('canvas')?.getAttribute('aria-label') ?? ''),
    );
    expect(label[0]).toMatch(/measured R: .*measured G: .*measured B: .*GGX fit R/);
    expect(label[1]).toMatch(
      /measured θd = 0 slice, less the ABC fit’s diffuse, ÷ its V: .*ABC fit \(dashed\): .*Shifted gamma fit/,
    );
  });

  it('the 3-D lobe is scaled to the larger peak of the measured green channel and the GGX fit (analytic)', async () => {
    const label = await page.$eval('.measured-spheres .lobe-3d canvas', (c) => c.getAttribute('aria-label'));
    const light = (30 * Math.PI) / 180; // the schema's default light
    const l = [-Math.sin(light), 0, Math.cos(light)];
    const ggx = (await fits()).ggx;
    const peak = (f) =>
      Math.max(
        ...Array.from({ length: 179 }, (_, i) => {
          const t = ((i - 89) * Math.PI) / 180; // the plane of incidence, where an isotropic lobe peaks
          return f(l, [Math.sin(t), 0, Math.cos(t)])[1];
        }),
      );
    const want = Math.max(peak(modelBRDF('abc', TRUTH)), peak(modelBRDF('ggx', ggx.params)));
    const shown = Number(/scaled to ([\d.e+-]+) \/sr/.exec(label)?.[1]);
    expect(label).toMatch(/3-D lobe of the measured table's green channel \(solid\) and the GGX fit \(wireframe\)/);
    expect(Math.abs(shown / want - 1)).toBeLessThan(0.05);
  });

  it(
    'the spheres are drawn from the 3-D textures: ' + 'copper-coloured highlight (R > G > B, as f0 0.9 / 0.6 / 0.3)',
    async () => {
      // no channel clips
      await page.evaluate(() => globalThis.__shadingLab.widgets.measured.update({ exposure: 0.05 }));
      await page.$eval('.measured-spheres', (e) => e.scrollIntoView());
      await untilIdle(page);
      await page.addStyleTag({ content: '.measured-spheres .sphere-labels { display: none; }' });
      const png = await shot(page, '.measured-spheres canvas');
      const brightest = await withPixels(page, png, (image) => {
        const best = [0, 0, 0];
        const [cx, cy, r] = [image.width / 4, image.height / 2, 0.4 * image.height]; // inside the left (measured) disc
        for (let y = 0; y < image.height; y++) {
          for (let x = 0; x < image.width / 2; x++) {
            if ((x - cx) ** 2 + (y - cy) ** 2 > r * r) continue;
            const i = 4 * (y * image.width + x);
            if (image.data[i] + image.data[i + 1] + image.data[i + 2] > best[0] + best[1] + best[2])
              best.splice(0, 3, image.data[i], image.data[i + 1], image.data[i + 2]);
          }
        }
        return best;
      });
      expect(brightest[0]).toBeGreaterThan(brightest[1]);
      expect(brightest[1]).toBeGreaterThan(brightest[2]);
      expect(brightest[0]).toBeGreaterThan(100);
    },
  );

  it('"load this fit into BRDF lobe" sets brdf-lobe to ABC with Cook-Torrance V and the mean f0', async () => {
    await page.click('.measured-fits button[data-model="abc"][data-target="lobe"]');
    await untilIdle(page);
    const lobe = await getState(page, 'lobe');
    expect(lobe.D).toBe('abc');
    expect(lobe.V).toBe('cookTorrance');
    expect(lobe.f0).toBeCloseTo((0.9 + 0.6 + 0.3) / 3, 2);
  });

  // the button is pressed where it is, not at a point: the lobe test's smooth scroll may still be moving the page
  it('"NDF explorer" opens ndf.html with the ABC fit’s half width (bisection on D) and its a2', async () => {
    const toNdf = () => page.$eval('.measured-fits button[data-model="abc"][data-target="ndf"]', (b) => b.click());
    const ndf = await pageOpenedBy(browser, toNdf, 'ndf.html');
    await ndf.waitForFunction(() => globalThis.__shadingLab?.widgets?.ndf, { timeout: WAIT_MS, polling: 250 });
    const state = await ndf.evaluate(() => globalThis.__shadingLab.widgets.ndf.getState());
    expect(state.hwhm).toBeCloseTo(
      ndfHalfWidthDeg((c) => ndfABC(c, TRUTH.a1, TRUTH.a2)),
      1,
    ); // 4 digits in the URL
    expect(state.abcA2).toBeCloseTo(TRUTH.a2, 2);
    await ndf.close();
  });

  it(
    'ndf-explorer draws the measured θd = 0 slice / peak on its log plot: ' +
      'the slice computed in Node from the same file and fit',
    async () => {
      const f = await fits();
      const want = measuredNdfSlice(parseMerl(readFileSync(file).buffer).table, f.abc); // ABC: the best fit
      const toNdf = () => page.$eval('.measured-fits button[data-model="abc"][data-target="ndf"]', (b) => b.click());
      const ndf = await pageOpenedBy(browser, toNdf, 'ndf.html');
      await ndf.waitForFunction(() => globalThis.__shadingLab?.widgets?.ndf?.getMeasuredCurve(), { timeout: WAIT_MS });
      const curve = await ndf.evaluate(() => globalThis.__shadingLab.widgets.ndf.getMeasuredCurve());
      expect(curve.label).toBe('measured: synthetic-abc.binary, θd = 0 slice / peak');
      const drawn = new Map(curve.points);
      let compared = 0;
      THETA_H_DEG.forEach((deg, i) => {
        if (!(want[i] > 1e-5)) return expect(drawn.has(deg)).toBe(false); // below the plot: not drawn
        expect(Math.abs(drawn.get(deg) / want[i] - 1), `θh ${deg}°`).toBeLessThan(5e-3); // 3 digits in the URL
        compared++;
      });
      expect(compared).toBeGreaterThan(80);
      expect(curve.points).toHaveLength(compared); // nothing drawn between the nodes
      const aria = await ndf.$$eval('figure.plot canvas', (c) => c[1].getAttribute('aria-label'));
      expect(aria).toMatch(/D\(θh\) \/ D\(0\), log scale.*measured: synthetic-abc\.binary.*ABC \(dashed\): /);
      await ndf.close();
    },
  );

  it('a bad file dropped on the zone is refused with its message, and the ABC table stays', async () => {
    await page.evaluate(() => {
      const dt = new DataTransfer();
      dt.items.add(new File([new Uint8Array(1000)], 'broken.binary'));
      document
        .querySelector('.measured-drop')
        .dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
    });
    await page.waitForFunction(
      () => document.querySelector('.widget-measured-brdf .notices')?.textContent.includes('broken.binary'),
      { timeout: WAIT_MS, polling: 300 },
    );
    const notice = await page.$eval('.widget-measured-brdf .notices', (e) => e.textContent);
    expect(notice).toMatch(/broken\.binary: Wrong dimensions 0 × 0 × 0.*The BRDF shown before is kept\./);
    expect(await page.$eval('.measured-source', (e) => e.textContent)).toMatch(/synthetic-abc\.binary/);
    expect((await fits()).abc.params.a1).toBeCloseTo(TRUTH.a1, 0);
    expect(page.errors).toEqual([]);
  });
});
