// Typeset formulas in Chromium: the visibility chapter's formulas become MathML that the browser lays out.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchBrowser, open, settle } from './helpers.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

describe('formulas', () => {
  it('visibility.html: the talk’s f = F G D / (4 (n·l)(n·v)) and V = G / ((n·l)(n·v)) as laid-out MathML', async () => {
    const page = await open(browser, 'visibility.html');
    await page.waitForFunction(
      () => document.querySelectorAll('.formula math').length === document.querySelectorAll('.formula').length,
      { timeout: 30_000 },
    );
    await settle(page, 300);
    const first = await page.$eval('.formula math', (m) => {
      const fracs = [...m.querySelectorAll('mfrac')];
      const text = (el) => el.textContent.replace(/\s+/g, '');
      return {
        display: m.getAttribute('display'),
        size: [m.getBoundingClientRect().width, m.getBoundingClientRect().height],
        fractions: fracs.map((f) => [text(f.children[0]), text(f.children[1])]),
      };
    });
    expect(first.display).toBe('block');
    expect(first.size[0]).toBeGreaterThan(200); // laid out by the browser's MathML, not left as source
    expect(first.size[1]).toBeGreaterThan(30); // fractions stack
    expect(first.fractions).toEqual([
      // the talk's vectors in bold (mathematical bold letters)
      ['F(𝐥,𝐡)G(𝐥,𝐯,𝐡)D(𝐡)', '4(𝐧⋅𝐥)(𝐧⋅𝐯)'],
      ['F(𝐥,𝐡)V(𝐥,𝐯)D(𝐡)', '4'],
      ['G(𝐥,𝐯,𝐡)', '(𝐧⋅𝐥)(𝐧⋅𝐯)'],
    ]);
    expect(await page.$eval('.formula', (p) => p.title)).toMatch(/^f\(l, v\) = F\(l, h\)/); // the plain form stays
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
