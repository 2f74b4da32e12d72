// Typeset formulas in Chromium: every chapter's formulas become MathML that the browser lays out, and a widget's
// live formula shows the model's numbers (recomputed here from the closed form) and lights up with its controls.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, afterFrames, launchBrowser, open as openLarge, setControl, untilIdle, widget } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';

/**
 * A page in a small window, its progressive views (the lab's reference, the media's path tracer) stopped at one batch
 * of 8 samples (sampleTarget in debug-hooks.js): the claims here are the formulas' MathML, not the pictures.
 */
const open = (browser, path) => openLarge(browser, path, { ...SMALL_VIEWPORT, maxSamples: 8 });

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** Waits until every slot has its widget (they mount one after another) and every formula is MathML. */
const typeset = (page) =>
  page.waitForFunction(
    () =>
      [...document.querySelectorAll('[data-tex], .widget-formula')].every((el) => el.querySelector('math')) &&
      document.querySelectorAll('.widget-formula').length === document.querySelectorAll('[data-widget]').length &&
      document.querySelectorAll('[data-widget]').length >= document.querySelectorAll('[data-slot]').length,
    { timeout: WAIT_MS },
  );

/** What the page's formulas came out as: counts, layout sizes, and any formula KaTeX refused. */
const formulaReport = (page) =>
  page.evaluate(() => {
    const all = [...document.querySelectorAll('[data-tex], .widget-formula')];
    return {
      count: all.length,
      refused: all.filter((el) => el.title.startsWith('Formula not typeset')).map((el) => el.dataset.tex),
      unlaid: all
        .map((el) => el.querySelector('math'))
        .filter((m) => m.closest('[hidden]') === null && m.getBoundingClientRect().width < 4).length,
    };
  });

describe('formulas', () => {
  it('visibility.html: the talk’s f = F G D / (4 (n·l)(n·v)) and V = G / ((n·l)(n·v)) as laid-out MathML', async () => {
    const page = await open(browser, 'visibility.html');
    await typeset(page);
    await untilIdle(page);
    const first = await page.$eval('p.formula math', (m) => {
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
    expect(await page.$eval('p.formula', (p) => p.title)).toMatch(/^f\(l, v\) = F\(l, h\)/); // the plain form stays
    expect(page.errors).toEqual([]);
    await page.close();
  });

  const CHAPTERS = ['fresnel', 'media', 'microfacets', 'ndf', 'brdf', 'diffuse', 'rendering', 'performance'];
  it.each(CHAPTERS)('%s.html: every formula and every widget’s live formula is laid-out MathML', async (name) => {
    const page = await open(browser, `${name}.html`);
    await typeset(page);
    await untilIdle(page);
    const report = await formulaReport(page);
    expect(report.count).toBeGreaterThan(1);
    expect(report.refused).toEqual([]);
    expect(report.unlaid).toBe(0);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('fresnel-curves: F0 = ((n − 1)/(n + 1))² follows the IOR control, and its symbol lights up with it', async () => {
    const page = await open(browser, 'embed.html?w=fresnel-curves&materials=manual');
    await widget(page, 'fresnel-curves');
    await typeset(page);
    const formulaText = () => page.$eval('.widget-formula math', (m) => m.textContent);
    for (const n of [2, 1.33]) {
      await setControl(page, 'Custom IOR', n);
      const f0 = ((n - 1) / (n + 1)) ** 2; // the closed form, here
      await page.waitForFunction(
        (x) => document.querySelector('.widget-formula math')?.textContent.includes(x),
        { timeout: WAIT_MS },
        f0.toFixed(3),
      );
      expect(await formulaText()).toContain((1 - f0).toFixed(3)); // Schlick's 1 − F0
    }

    const lit = () =>
      page.evaluate(() => ({
        symbols: [...document.querySelectorAll('.widget-formula [data-symbol="ior"]')].map((s) =>
          s.classList.contains('is-lit'),
        ),
        control: [...document.querySelectorAll('.lil-controller.is-lit')].map(
          (c) => c.querySelector('.lil-name').textContent,
        ),
      }));
    const iorInput = await page.evaluateHandle(() =>
      [...document.querySelectorAll('.lil-controller')]
        .find((c) => c.querySelector('.lil-name').textContent === 'Custom IOR')
        .querySelector('input'),
    );
    // focusing the control lights its symbol (both occurrences of n), leaving it puts it out
    await iorInput.focus();
    expect(await lit()).toEqual({ symbols: [true, true], control: ['Custom IOR'] });
    await page.evaluate(() => document.activeElement.blur());
    expect(await lit()).toEqual({ symbols: [false, false], control: [] });
    // hovering the symbol lights its control, and back
    const symbol = await page.$('.widget-formula [data-symbol="ior"]');
    await symbol.hover();
    expect((await lit()).control).toEqual(['Custom IOR']);
    await page.mouse.move(1, 1);
    expect((await lit()).control).toEqual([]);
    // the symbol is in the tab order; Enter on it goes to its control
    expect(await symbol.evaluate((s) => (s.focus(), document.activeElement === s && s.tabIndex))).toBe(0);
    expect((await lit()).control).toEqual(['Custom IOR']);
    await page.keyboard.press('Enter');
    expect(await page.evaluate(() => document.activeElement.closest('.lil-controller')?.textContent)).toMatch(
      /^Custom IOR/,
    );
    expect(page.errors).toEqual([]);
    await page.close();
  });
});

describe('formulas in data: a tour step’s text and an exercise’s prompt ($…$ TeX, never HTML)', () => {
  /** The formulas under `selector` once typeset: their MathML's text (not its TeX annotation), title, width. */
  const inlineFormulas = async (page, selector) => {
    await page.waitForFunction(
      (sel) => {
        const all = [...document.querySelectorAll(`${sel} [data-tex]`)];
        return all.length > 0 && all.every((el) => el.querySelector('math'));
      },
      { timeout: WAIT_MS },
      selector,
    );
    return page.$$eval(`${selector} [data-tex]`, (els) =>
      els.map((el) => ({
        math: el.querySelector('math semantics > :first-child').textContent.replace(/\s+/g, ''),
        title: el.title,
        width: el.querySelector('math').getBoundingClientRect().width,
      })),
    );
  };

  it('tour, visibility-implicit: the talk’s G = (n·l)(n·v) is MathML with bold vectors, titled in plain', async () => {
    const page = await open(browser, 'tour.html#visibility-implicit');
    const formulas = await inlineFormulas(page, '.tour-text');
    expect(formulas[0]).toMatchObject({ math: 'G=(𝐧⋅𝐥)(𝐧⋅𝐯)', title: 'G = (n·l)(n·v)' });
    expect(formulas.every((f) => f.width > 4 && !f.title.startsWith('Formula not typeset'))).toBe(true);
    expect(await page.$eval('.tour-text', (p) => p.textContent)).not.toContain('$');
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('exercise shader-ggx-tiny-alpha: GGX D = α²/(π((n·h)²(α² − 1) + 1)²) is a MathML fraction', async () => {
    const page = await open(browser, 'exercises.html#shader-ggx-tiny-alpha');
    const formulas = await inlineFormulas(page, '.exercise-prompt');
    expect(formulas[0].title).toBe('D = α²/(π ((n·h)² (α² − 1) + 1)²)');
    const fraction = await page.$eval('.exercise-prompt [data-tex] mfrac', (f) =>
      [...f.children].map((c) => c.textContent.replace(/\s+/g, '')),
    );
    expect(fraction).toEqual(['α2', 'π((𝐧⋅𝐡)2(α2−1)+1)2']);
    expect(formulas.every((f) => f.width > 4 && !f.title.startsWith('Formula not typeset'))).toBe(true);
    expect(page.errors).toEqual([]);
    await page.close();
  });

  it('a hostile prompt stays inert: \\href{javascript:…} is not a link, <img onerror> is text', async () => {
    const prompt = 'Costs \\$5. $\\href{javascript:window.__pwned=1}{x}$ <img src=x onerror="window.__pwned=2">';
    const set = [{ id: 'hostile', chapter: 'diffuse', title: 'Hostile', prompt, grader: 'lambert-radiance' }];
    Object.assign(set[0], { params: { cLight: 1, thetaDeg: 0 }, tolerance: 0.1 });
    const src = encodeURIComponent(`data:application/json,${JSON.stringify(set)}`);
    const page = await open(browser, `exercises.html?src=${src}#hostile`);
    await inlineFormulas(page, '.exercise-prompt');
    const seen = await page.$eval('.exercise-prompt', (p) => ({
      text: p.textContent,
      html: p.querySelectorAll('img, a, script, [onerror]').length,
      links: [...p.querySelectorAll('[href]')].map((e) => e.getAttribute('href')),
    }));
    expect(seen.text).toContain('Costs $5. ');
    expect(seen.text).toContain('<img src=x onerror="window.__pwned=2">'); // shown as text, not parsed
    expect(seen.html).toBe(0); // no element made from the prompt's text
    expect(seen.links).toEqual([]); // KaTeX, untrusted, draws \\href as an error mark, not a link
    await page.click('.exercise-prompt [data-tex]');
    await afterFrames(page, 4); // what a click on a link would do, counted in frames
    expect(await page.evaluate(() => globalThis.__pwned)).toBeUndefined();
    expect(page.errors).toEqual([]);
    await page.close();
  });
});
