// The Fresnel page's comparison past the talk (metal-fresnel) in a real Chromium: the table shows src/math's
// numbers (the worst error of Schlick, Gulbrandsen's edge tint and F82-tint for every channel of the five metals),
// the GUI and the URL change the metal, a bad value gives a notice and keeps the last good state.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { getState, launchBrowser, open, setControl, shot, widget } from './helpers.js';
import { errorTable } from '../../src/widgets/metal-fresnel/model.js';
import { errorWords, tableSummary } from '../../src/widgets/metal-fresnel/words.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const ROOT = '[data-slot="metal-fresnel"]';
const rows = errorTable();

describe('metal-fresnel on the Fresnel page', () => {
  it('tables every channel of the five metals with the errors src/math computes (float64, in Node)', async () => {
    const page = await open(browser, 'fresnel.html#metals');
    await widget(page, 'metals');
    const cells = await page.$$eval(`${ROOT} .metal-errors tbody tr`, (trs) =>
      trs.map((tr) => [...tr.children].map((c) => c.textContent)),
    );
    expect(cells).toHaveLength(15);
    cells.forEach((cell, i) => {
      const r = rows[i];
      expect(cell.slice(0, 5)).toEqual([
        r.name,
        'RGB'[r.channel],
        r.fit.f0.toFixed(3),
        r.fit.tint.toFixed(3),
        r.fit.edgeTint.toFixed(3),
      ]);
      expect(cell.slice(5)).toEqual(['schlick', 'gulbrandsen', 'f82Tint'].map((m) => errorWords(r.worst[m].value)));
    });
    expect(await page.$eval(`${ROOT} .metal-summary`, (p) => p.textContent)).toBe(tableSummary(rows));
    const section = await page.$eval('#metals', (s) => s.textContent);
    expect(section).toMatch(/beyond the 2013 talk/);
    expect(section).toMatch(/Hoffman \(2019/);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('the GUI changes the metal (plot, marked rows, URL); a bad metal in the URL keeps the default', async () => {
    const page = await open(browser, 'fresnel.html');
    await widget(page, 'metals');
    const before = await shot(page, `${ROOT} .plots`);
    await setControl(page, 'Metal', 'Gold', ROOT);
    expect(await shot(page, `${ROOT} .plots`)).not.toBe(before);
    const marked = await page.$$eval(`${ROOT} tr.selected th`, (ths) => ths.map((th) => th.textContent));
    expect(marked).toEqual(['Gold', 'Gold', 'Gold']);
    expect(await page.$eval(`${ROOT} .plots`, (p) => p.textContent)).toMatch(/^Gold: reflectance/);
    expect(page.url()).toMatch(/metals\.metal=gold/);
    const bad = await open(browser, 'fresnel.html?metals.metal=unobtainium&metals.models=schlick');
    await widget(bad, 'metals');
    expect(await bad.$eval(`${ROOT} .notice`, (n) => n.textContent)).toMatch(/unobtainium/);
    expect(await getState(bad, 'metals')).toEqual({ metal: 'aluminum', models: ['schlick'] });
    expect([...page.errors, ...bad.errors]).toEqual([]);
    await Promise.all([page.close(), bad.close()]);
  });
});
