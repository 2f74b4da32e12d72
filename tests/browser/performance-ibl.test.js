// The performance page's brushed-metal part of image-based lighting (src/pages/performance-ibl.js): one row per
// method of the report's anisotropic case (bench/ibl.js), its GPU time and errors as the report holds them, the
// sources of what each method does named, the reference's own noise said, and its table in a named scroll box.
import { readFileSync } from 'node:fs';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open } from './helpers.js';
import { PUBLISHED } from '../../bench/publish-report.js';

const { ibl } = JSON.parse(readFileSync(PUBLISHED, 'utf8'));
const brushed = ibl.rows.filter((r) => r.anisotropy > 0);

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('performance page: brushed metal under an environment', () => {
  it('lists each method of the report’s anisotropic case with its time and errors against the reference', async () => {
    const page = await open(browser, 'performance.html');
    await page.waitForSelector('#ibl-anisotropic table');
    const part = await page.$eval('#ibl-anisotropic', (el) => {
      const table = el.querySelector('table.data-table'); // not the chart's legend
      return {
        heading: el.querySelector('h3').textContent,
        words: [...el.querySelectorAll(':scope > ul > li')].map((li) => li.textContent),
        rows: [...table.tBodies[0].rows].map((tr) => [...tr.cells].map((td) => td.textContent)),
        head: [...table.tHead.rows[0].cells].map((th) => th.textContent),
        caption: table.caption.textContent,
        box: table.parentElement.getAttribute('aria-label'),
        notes: [...el.querySelectorAll('p.source')].map((p) => p.textContent),
        charts: el.querySelectorAll('figure').length,
      };
    });
    expect(part.heading).toMatch(/Brushed metal/);
    expect(part.box).toBe(`Table: ${part.heading}`);
    expect(part.head).toEqual(['Method', 'GPU ms', 'RMS error', 'relative']);
    expect(part.caption).toMatch(new RegExp(`ms.*radiance.*${ibl.setup.referenceSamples}-sample reference`));
    // the report's figures, formatted as the page says them
    expect(part.rows).toEqual(
      brushed.map((r) => [
        r.samples ? `importance, N = ${r.samples}` : `split-sum, ${r.bent ? 'bent reflection' : 'mirror direction'}`,
        r.ms.toFixed(1),
        r.rms.toExponential(2),
        `${(r.relative * 100).toFixed(1)} %`,
      ]),
    );
    expect(part.words).toHaveLength(3);
    expect(part.words[0]).toMatch(/bent reflection vector.*Filament.*McAuley 2015.*Revie 2012.*three\.js/);
    expect(part.words[1]).toMatch(/mirror direction/);
    expect(part.words[2]).toMatch(/Importance sampling.*visible normals.*Dupuy & Benyoub 2023/);
    const [check] = ibl.referenceChecks.filter((c) => c.anisotropy > 0);
    expect(part.notes).toEqual([expect.stringContaining(`own noise at ${(check.noise * 100).toFixed(2)} %`)]);
    expect(part.charts).toBeGreaterThanOrEqual(1);
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
