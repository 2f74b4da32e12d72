// The white furnace with energy compensation, in Chromium: with F = 1 both compensations give every sphere an
// albedo of 1, so each pixel inside each sphere reads back as the white background (the truth: a surface that
// loses nothing is invisible in the furnace); without compensation the rough sphere stays grey.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser, open, shot, untilIdle, untilSteady, widget, withPixels } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const ALPHAS = ['0.05', '0.5', '1.0']; // the sweep's option keys

/** The darkest channel value inside each of the row's spheres (points within 0.9 of the radius). */
function darkestPerSphere(page, png, cells) {
  return withPixels(
    page,
    png,
    `(image) => Array.from({ length: ${cells} }, (_, i) => {
    const cell = image.width / ${cells};
    const radius = Math.min(cell, image.height) / 2 / 1.08; // the grid's camera half extent (sphere-grid.js)
    const [cx, cy] = [cell * (i + 0.5), image.height / 2];
    let darkest = 255;
    for (let y = -0.9; y <= 0.9; y += 0.05) {
      for (let x = -0.9; x <= 0.9; x += 0.05) {
        if (x * x + y * y > 0.81) continue;
        const k = (Math.round(cy + y * radius) * image.width + Math.round(cx + x * radius)) * 4;
        darkest = Math.min(darkest, image.data[k], image.data[k + 1], image.data[k + 2]);
      }
    }
    return darkest;
  })`,
  );
}

describe('energy: compensated furnace spheres', () => {
  for (const compensation of ['kullaConty', 'turquin', 'none']) {
    it(
      `${compensation}: ` +
        (compensation === 'none' ? 'the rough sphere stays grey' : 'every sphere reads back as the white background'),
      async () => {
        const page = await open(
          browser,
          `embed.html?w=energy&alphas=${ALPHAS.join(',')}&compensation=${compensation}`,
          {
            width: 1200,
            height: 900,
          },
        );
        await widget(page, 'energy');
        await untilSteady(page, 'drawCalls'); // the spheres drawn with their tables, nothing more to come
        expect((await page.evaluate(() => globalThis.__shadingLab.widgets['energy'].getAlbedos())).length).toBe(
          ALPHAS.length,
        );
        const darkest = await darkestPerSphere(page, await shot(page, '.sphere-grid canvas'), ALPHAS.length);
        console.log(
          `furnace, ${compensation}: darkest 8-bit value inside the spheres α ` +
            `${ALPHAS.join(', ')}: ${darkest.join(', ')}`,
        );
        if (compensation === 'none')
          expect(darkest[2]).toBeLessThan(200); // E(1) = 1 − ln 2 at α = 1: sRGB 150
        else for (const d of darkest) expect(d).toBeGreaterThanOrEqual(254);
        expect(page.errors).toEqual([]);
        await page.close();
      },
    );
  }
});

describe("energy: the coloured metal's random walk", () => {
  it(
    'runs in a worker: each α change asks walk-worker.js and returns at once with the walk pending, ' +
      "and the newest α's points (walkPoints) are shown",
    async () => {
      const { walkPoints } = await import('../../src/widgets/energy/compensation.js');
      const { materialByKey } = await import('../../src/math/materials.js');
      const page = await open(browser, 'embed.html?w=energy&alphas=0.5', { width: 1200, height: 900 });
      await widget(page, 'energy');
      const walkShown = () =>
        page.waitForFunction(
          () => document.querySelector('.data-table caption') && !document.querySelector('.walk-pending'),
          { timeout: WAIT_MS },
        );
      await walkShown();
      await untilIdle(page);
      await page.evaluate(() => {
        window.__asked = []; // what the page sends its workers from now on
        const post = Worker.prototype.postMessage;
        Worker.prototype.postMessage = function recorded(data, ...rest) {
          window.__asked.push(data.alpha);
          return post.call(this, data, ...rest);
        };
        window.__longTasks = [];
        new PerformanceObserver((list) => window.__longTasks.push(...list.getEntries().map((e) => e.duration))).observe(
          { type: 'longtask' },
        );
      });
      // a slider drag: each next α comes while the last walk still runs, and the change returns with it pending
      // (a walk on the main thread, ~1.1 s, would be done, or the page frozen, by the time update() returns)
      const alphas = [0.3, 0.55, 0.05, 1];
      for (const alpha of alphas) {
        const pending = await page.evaluate((a) => {
          globalThis.__shadingLab.widgets['energy'].update({ metalAlpha: a });
          return Boolean(document.querySelector('.walk-pending'));
        }, alpha);
        expect(pending, `α = ${alpha}: the walk row says it is running`).toBe(true);
      }
      await walkShown();
      await untilIdle(page);
      expect(await page.evaluate(() => window.__asked)).toEqual(alphas); // one walk per α, each in the worker
      expect(
        page
          .workers()
          .map((w) => w.url())
          .some((u) => /walk-worker/.test(u)),
      ).toBe(true);
      // a figure, not a bound: the time a task takes depends on what else the machine runs
      const longest = await page.evaluate(() => Math.max(0, ...window.__longTasks));
      console.log(`energy: longest main-thread task over 4 α changes: ${longest.toFixed(0)} ms (the walk ~1100 ms)`);
      const { caption, head } = await page.evaluate(() => {
        const t = [...document.querySelectorAll('.data-table')].find((x) =>
          x.caption?.textContent.includes('seen head-on'),
        );
        const walkRow = [...t.querySelectorAll('tbody tr')].at(-1);
        return { caption: t.caption.textContent, head: walkRow.cells[2].textContent };
      });
      expect(caption).toMatch(/at α = 1,/);
      const expected = walkPoints(1, materialByKey('gold').linear)[0]
        .albedo.map((x) => x.toFixed(3))
        .join(', ');
      expect(head).toBe(expected); // the newest α's walk, not a stale one drawn over it
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );
});

describe('energy: the picture the words speak of', () => {
  it(
    'the spheres come first, each ringed where it vanishes (radius 1.03/1.08 of half its cell), and gold is shown in ' +
      'patches of the colours src/math/albedo-table.js gives head-on',
    async () => {
      const { buildAlbedoTableGGX, specularAlbedoFromTable } = await import('../../src/math/albedo-table.js');
      const { materialByKey } = await import('../../src/math/materials.js');
      const { linearToSrgb } = await import('../../src/math/color.js');
      const page = await open(browser, 'embed.html?w=energy&compensation=kullaConty&metal=gold&metalAlpha=0.8', {
        width: 1280,
        height: 800,
      });
      await widget(page, 'energy');
      const layout = await page.evaluate(() => {
        const top = (q) => document.querySelector(q).getBoundingClientRect().top;
        const canvas = document.querySelector('.sphere-grid canvas').getBoundingClientRect();
        const circles = [...document.querySelectorAll('.furnace-outlines circle')];
        return {
          spheres: top('.sphere-grid'),
          firstPlot: top('.widget-energy figure.plot'),
          inView: canvas.bottom <= window.innerHeight,
          cell: canvas.width / 5,
          diameters: circles.map((c) => c.getBoundingClientRect().width),
          caption: document.querySelector('.furnace-caption').textContent,
        };
      });
      expect(layout.spheres).toBeLessThan(layout.firstPlot);
      expect(layout.inView).toBe(true);
      expect(layout.caption).toMatch(/disappears.*Kulla–Conty puts back .* every sphere disappears/);
      expect(layout.diameters).toHaveLength(5);
      for (const d of layout.diameters) expect(Math.abs(d - (layout.cell / 1.08) * 1.03)).toBeLessThan(3);

      const patches = await page.$$eval('.metal-patches figure', (figs) =>
        figs.map((f) => {
          const patch = f.querySelector('.patch');
          const rgb = getComputedStyle(patch).backgroundColor.match(/\d+/g).map(Number);
          return { name: f.textContent, width: patch.getBoundingClientRect().width, rgb };
        }),
      );
      expect(patches.map((p) => p.name.split(' (')[0])).toEqual([
        'single scattering',
        'Kulla–Conty',
        'Turquin',
        'random walk',
      ]);
      const table = buildAlbedoTableGGX();
      const gold = materialByKey('gold').linear;
      ['none', 'kullaConty', 'turquin'].forEach((key, i) => {
        expect(patches[i].width).toBeGreaterThanOrEqual(96);
        const expected = gold.map((f0) =>
          Math.round(linearToSrgb(specularAlbedoFromTable(table, 1, 0.8, f0, key)) * 255),
        );
        patches[i].rgb.forEach((c, ch) => expect(Math.abs(c - expected[ch])).toBeLessThanOrEqual(1));
      });
      expect(page.errors).toEqual([]);
      await page.close();
    },
  );
});
