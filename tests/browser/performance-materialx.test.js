// The performance page's OpenPBR section shows the app against MaterialX's reference shader (src/pages/
// openpbr-materialx.js): a row per material of the bench's list (tests/support/materialx-materials.js), each
// material's figures as the published report holds them, the random walk's figure of its stack beside it, and the
// fuzz rows naming the lobe they are measured against. On a phone the table scrolls in its own named box.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { baseUrl, launchBrowser, WAIT_MS } from './helpers.js';
import { openPage } from './harness.js';
import report from '../../src/pages/data/bench-report.json';
import { MATERIALX_BENCH_MATERIALS } from '../support/materialx-materials.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const open = (size) =>
  openPage(browser, baseUrl(), 'performance.html', {
    ...size,
    beforeLoad: async (p) => {
      await p.setViewport(size);
      p.setDefaultTimeout(WAIT_MS);
    },
  });

/** The table's rows, each its cells' text, and the heading of the section it is in. */
const tableOf = (page) =>
  page.$eval('#materialx-table', (t) => ({
    rows: [...t.tBodies[0].rows].map((r) => [...r.cells].map((c) => c.textContent)),
    section: t.closest('section').querySelector('h2').textContent,
  }));

describe('performance page: OpenPBR against MaterialX’s reference shader', () => {
  it('a row per material of the bench, with the report’s figures and the walk’s beside them', async () => {
    const page = await open({ width: 1280, height: 800 });
    await page.waitForSelector('#latency'); // the page's last section: everything is drawn
    const { rows, section } = await tableOf(page);
    expect(section).toMatch(/^The layers of OpenPBR Surface/);
    expect(rows.map((r) => r[0])).toEqual(MATERIALX_BENCH_MATERIALS.map((m) => m.label));
    const walk = Object.fromEntries(
      report.families.find((f) => f.key === 'openpbr-layers').variants.map((v) => [v.key, v.error.maxAbs]),
    );
    report.materialx.rows.forEach((r, i) => {
      const pct = (x) => (x < 1e-4 ? '< 0.01 %' : `${(x * 100).toFixed(2)} %`);
      expect(rows[i][2]).toBe(r.glsl.maxRelative.map(pct).join(' / '));
      if (r.layers.includes('fuzz'))
        expect(rows[i][6]).toMatch(/against Zeltner, Burley & Chiang 2022’s lobe as MaterialX implements it/);
    });
    const at = (name) => rows[MATERIALX_BENCH_MATERIALS.findIndex((m) => m.name === name)];
    expect(at('layers-base')[6]).toContain(walk.talk.toFixed(3));
    expect(at('layers-coat')[6]).toContain(walk.coat.toFixed(3));
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('on a phone (390 px) the table scrolls in a box of its own, named, and the page is no wider', async () => {
    const page = await open({ width: 390, height: 844, isMobile: true, hasTouch: true });
    await page.waitForSelector('#latency'); // the page's last section: everything is drawn
    const box = await page.$eval('#materialx-table', (t) => ({
      className: t.parentElement.className,
      label: t.parentElement.getAttribute('aria-label'),
      tabIndex: t.parentElement.tabIndex,
      scrolls: t.parentElement.scrollWidth > t.parentElement.clientWidth,
    }));
    expect(box).toEqual({
      className: 'table-scroll',
      label: 'Table: OpenPBR against MaterialX',
      tabIndex: 0,
      scrolls: true,
    });
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(390);
    await page.close();
  });
});
