// Accessibility of every registered widget in a real Chromium: each canvas says in words what it shows and
// says something new when the state changes, every control is reachable by Tab, the interactive canvases
// answer the keyboard, and the words carry the numbers (checked against closed forms and the F0 table).
// Each widget is mounted once, on a page its tests share in turn (a mount is most of a test's time on software
// WebGL): the keyboard and the numbers are checked after the words, from the state the widget is left in, set
// where a check needs one (the mode shown, the materials plotted). Every page runs under the app's
// Content-Security-Policy with no violation; and a few of them, mounted here anyway, pass axe-core's WCAG 2.2 A and
// AA rules as the embed that shows one widget (axe.test.js checks every other page so).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, getState, launchBrowser, open, shot, untilIdle, widget } from './helpers.js';
import { recordViolations } from './under-policy.js';
import { axeViolations } from './axe-run.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { sphereZoneFractions } from '../../src/math/zones.js';
import { materialByKey } from '../../src/math/materials.js';

/** Per widget, a change that alters everything it draws. A new widget must add its own here. */
const CHANGES = {
  'fresnel-curves': { materials: ['gold', 'water'] },
  'fresnel-zones': { lightTheta: 100 },
  'f0-tables': { selected: 'silver' },
  'metal-fresnel': { metal: 'gold' },
  media: { medium: 'red' },
  surfaces: { theta: 60 },
  'subsurface-scale': { sigmaS: 5 },
  radiance: { distance: 5, lampRadius: 0.08, light: 'sodium' },
  'brdf-lobe': { alpha: 0.6 },
  'measured-brdf': { lightTheta: 50, phiD: 45, overlay: 'abc', sphereLight: 50 },
  'ndf-explorer': { hwhm: 15 },
  'visibility-explorer': { alpha: 0.2 },
  microfacets: { alpha: 0.8 },
  'anisotropic-microsurface': { theta: 60 }, // φ only moves the light along the plot's sweep; θ re-measures it
  energy: { alphas: ['0.25', '0.75'], metalAlpha: 0.5 },
  'diffuse-explorer': { sigma: 20, lightTheta: 60 },
  'material-lab': { alpha: 0.6 },
  'lighting-models': { alpha: 0.5 },
};
/** Extra URL state to keep software rendering quick (fewer path-traced samples). */
const QUICK = { media: '&samples=16', 'material-lab': '&refSamples=128', 'lighting-models': '&refSamples=128' };
const STATIC_PICTURE = /^Four metal spheres/; // the surfaces widget's room reflections do not depend on its state
/**
 * The embeds axe-core checks (the gallery's previews are such embeds, so axe stays out of their frames): one of each
 * kind, a WebGL view with a legend (fresnel-zones), tables (f0-tables), a plot beside a 3-D view (brdf-lobe) and the
 * largest panel (material-lab).
 */
const AXE_WIDGETS = ['fresnel-zones', 'f0-tables', 'brdf-lobe', 'material-lab'];

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** The widget's visible canvases (role, description) and its live summary. */
const readWords = (page) =>
  page.evaluate(() => ({
    canvases: [...document.querySelectorAll('.widget canvas')]
      .filter((c) => c.getClientRects().length)
      .map((c) => ({ role: c.getAttribute('role'), label: c.getAttribute('aria-label') ?? '' })),
    live: document.querySelector('.widget-live')?.textContent ?? '',
  }));

/**
 * Opens a widget alone, tall enough that every view is in sight and draws (the tallest, the measured BRDF's ten
 * canvases, end about 2,900 px down at 800 px wide), its progressive views capped at their fewest samples (one
 * batch or frame, sampleTarget in src/core/framework/debug-hooks.js): the words are the claim, not a converged
 * picture.
 */
const openWidget = async (query) => {
  const page = await open(browser, `embed.html?w=${query}`, {
    width: 800,
    height: 3200,
    maxSamples: 1,
    beforeLoad: (p) => p.evaluateOnNewDocument(recordViolations), // window.__csp (under-policy.js)
  });
  await widget(page, query.split('&')[0]);
  const outOfSight = await page.$$eval(
    '.widget canvas',
    (cs) => cs.filter((c) => c.getClientRects().length && c.getBoundingClientRect().bottom > innerHeight).length,
  );
  expect(outOfSight, 'canvases below the window, which draw nothing').toBe(0);
  return page;
};

/**
 * Presses Tab `n` times and returns, in order, the data-a11y-index of each element that took the focus (null for
 * one without). The key events go out on one DevTools session without a wait between them (it runs them in
 * order), and a focusin listener notes each focus: one round trip, not two a key.
 */
async function tabThrough(page, n) {
  await page.evaluate(() => {
    window.__focused = [];
    document.addEventListener('focusin', (e) => window.__focused.push(e.target.dataset?.a11yIndex ?? null));
  });
  const cdp = await page.createCDPSession();
  const tab = { key: 'Tab', code: 'Tab', windowsVirtualKeyCode: 9, nativeVirtualKeyCode: 9 };
  const keys = Array.from({ length: n }, () => ['rawKeyDown', 'keyUp']).flat();
  await Promise.all(keys.map((type) => cdp.send('Input.dispatchKeyEvent', { type, ...tab })));
  await cdp.detach();
  return page.evaluate(() => window.__focused);
}

/** Describes its canvases, says something new after CHANGES[name], and Tab reaches every named control. */
async function checkWordsAndTab(page, name) {
  expect(CHANGES[name], `add a state change for ${name} to CHANGES`).toBeDefined();
  const before = await readWords(page);
  for (const c of before.canvases) {
    expect(c.role).toBe('img');
    expect(c.label.length, c.label).toBeGreaterThan(30);
  }
  expect(before.live.length).toBeGreaterThan(30);

  await page.evaluate((n, change) => globalThis.__shadingLab.widgets[n].update(change), name, CHANGES[name]);
  // the live region speaks once changes settle (its pause is in the app's pending work, describe.js), and a
  // canvas may be described later still (after work off the main thread, which `pending` does not count):
  // wait for idle, then until all of them have new words
  const changed = (was, staticPicture) => {
    const now = [...document.querySelectorAll('.widget canvas')].filter((c) => c.getClientRects().length);
    const label = (c) => c.getAttribute('aria-label') ?? '';
    return (
      document.querySelector('.widget-live')?.textContent !== was.live &&
      now.every((c, i) => new RegExp(staticPicture).test(label(c)) || label(c) !== was.canvases[i]?.label)
    );
  };
  // (words that never change fail below, with the words in the message)
  await untilIdle(page);
  await page.waitForFunction(changed, { timeout: WAIT_MS }, before, STATIC_PICTURE.source).catch(() => {});
  const after = await readWords(page);
  expect(after.canvases.length).toBe(before.canvases.length);
  after.canvases.forEach((c, i) => {
    if (!STATIC_PICTURE.test(c.label))
      expect(c.label, `canvas ${i} kept its words: ${c.label}`).not.toBe(before.canvases[i].label);
  });
  expect(after.live).not.toBe(before.live);

  // Tab reaches every control of the panel, and each has a name a screen reader can read
  const controls = await page.evaluate(() => {
    const els = [...document.querySelectorAll('.lil-gui input, .lil-gui select, .lil-gui button')].filter(
      (el) => el.tabIndex >= 0 && !el.disabled && el.getClientRects().length,
    );
    els.forEach((el, i) => (el.dataset.a11yIndex = i));
    const nameOf = (el) =>
      (el.getAttribute('aria-labelledby')
        ? document.getElementById(el.getAttribute('aria-labelledby'))?.textContent
        : el.textContent
      )?.trim();
    return {
      count: els.length,
      unnamed: els.filter((el) => !nameOf(el)).map((el) => el.outerHTML.slice(0, 80)),
      stops: document.querySelectorAll('a[href], button, input, select, [tabindex]').length,
    };
  });
  expect(controls.count).toBeGreaterThan(0);
  expect(controls.unnamed).toEqual([]);
  await page.evaluate(() => document.activeElement?.blur());
  const reached = new Set((await tabThrough(page, controls.stops + 2)).filter((at) => at !== null));
  expect(reached.size).toBe(controls.count);
}

/** Sets `change` on the page's widget `name` and waits for idle (a check that needs a mode or materials shown). */
const setState = async (page, name, change) => {
  await page.evaluate((n, c) => globalThis.__shadingLab.widgets[n].update(c), name, change);
  await untilIdle(page);
};

/**
 * The keyboard and the numbers, per widget: [title, check(page)], run on its page after checkWordsAndTab, in this
 * order (the state each starts from is the one the last left, set here where the check needs it).
 */
const MORE = {
  'fresnel-zones': [
    [
      'the zones of n·v on an orthographic sphere are read out with their shares: 50%, 43.3%, 6.7%',
      async (page) => {
        await setState(page, 'fresnel-zones', { mode: 'zones-nv', lightTheta: 60 });
        // the shares are measured once the first frames pause (a GPU read-back), then described
        await page
          .waitForFunction(
            () => /goes rapidly to 1 [\d.]+%/.test(document.querySelector('.viewport canvas').ariaLabel),
            { timeout: WAIT_MS },
          )
          .catch(() => {}); // other words fail below, with the words in the message
        const label = await page.$eval('.viewport canvas', (c) => c.getAttribute('aria-label'));
        const shares = [...label.matchAll(/(barely changes|changes somewhat|goes rapidly to 1) ([\d.]+)%/g)].map(
          (m) => Number(m[2]) / 100,
        );
        expect(shares).toHaveLength(3);
        sphereZoneFractions().forEach((f, i) => expect(Math.abs(shares[i] - f)).toBeLessThan(0.01));
        expect(label).toMatch(/Light 60° from the view direction/);
      },
    ],
    [
      'the Fresnel-zones view moves its light with the arrow keys',
      async (page) => {
        await setState(page, 'fresnel-zones', { mode: 'zones-lh' });
        const before = await getState(page, 'fresnel-zones');
        await page.focus('.viewport canvas');
        await page.keyboard.press('ArrowDown');
        await page.keyboard.down('Shift');
        await page.keyboard.press('ArrowLeft');
        await page.keyboard.up('Shift');
        await untilIdle(page);
        const after = await getState(page, 'fresnel-zones');
        expect(after.lightTheta).toBeCloseTo(before.lightTheta + 5, 6);
        expect(after.lightPhi).toBeCloseTo(before.lightPhi + 1, 6);
      },
    ],
  ],
  'fresnel-curves': [
    [
      'a plot reads out its values: water reflects its tabulated F(0°) head-on and all light at 90°',
      async (page) => {
        await setState(page, 'fresnel-curves', { materials: ['water'] });
        const described = () => {
          const text = document.querySelector('.plot-canvas canvas').getAttribute('aria-label');
          return /Water exact/.test(text) && !/Gold/.test(text);
        };
        await page.waitForFunction(described, { timeout: WAIT_MS }).catch(() => {}); // the words fail below
        const label = await page.$eval('.plot-canvas canvas', (c) => c.getAttribute('aria-label'));
        const m = label.match(/Water exact: ([\d.]+) at 0, ([\d.]+) at 90/);
        expect(m, label).not.toBeNull();
        expect(label, 'gold no longer plotted').not.toMatch(/Gold/);
        expect(Number(m[1])).toBeCloseTo(materialByKey('water').linear[0], 3);
        expect(Number(m[2])).toBeCloseTo(1, 3);
        expect(label).toMatch(/Water Schlick \(dashed\)/);
      },
    ],
    [
      'a plot moves its cursor by keyboard and its readout follows',
      async (page) => {
        const caption = () => page.$eval('.readout caption', (el) => el.textContent);
        expect(await caption()).toMatch(/θ = 60\.00°/);
        await page.focus('.plot-canvas canvas');
        await page.keyboard.press('End');
        expect(await caption()).toMatch(/θ = 90\.00°/);
        await page.keyboard.press('Home');
        await page.keyboard.press('ArrowRight');
        expect(await caption()).toMatch(/θ = 0\.25°/);
      },
    ],
  ],
  'brdf-lobe': [
    [
      'the BRDF polar plot moves l and v, and the 3-D lobe orbits',
      async (page) => {
        const before = await getState(page, 'brdf-lobe');
        await page.focus('.polar-plot canvas');
        await page.keyboard.press('ArrowDown');
        await page.keyboard.press('ArrowLeft');
        await untilIdle(page);
        const after = await getState(page, 'brdf-lobe');
        expect([after.lightTheta, after.viewTheta]).toEqual([before.lightTheta + 5, before.viewTheta - 5]);
        const lobe = await shot(page, '.lobe-3d canvas');
        await page.focus('.lobe-3d canvas');
        await page.keyboard.press('ArrowLeft');
        await untilIdle(page); // the orbit's frame drawn
        expect(await shot(page, '.lobe-3d canvas')).not.toBe(lobe);
        expect(await getState(page, 'brdf-lobe')).toEqual(after); // orbiting is a view, not state
      },
    ],
  ],
  'ndf-explorer': [
    [
      'a row of spheres is probed by keyboard: the arrows move the probe, sphere to sphere',
      async (page) => {
        await page.focus('.sphere-grid canvas');
        for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
        const rows = () =>
          page.$$eval('.probe tr', (trs) =>
            Object.fromEntries(trs.map((tr) => [tr.cells[0].textContent, tr.cells[1].textContent])),
          );
        let probe = await rows();
        expect(probe.sphere).toBe('Blinn–Phong');
        // at x = 0.3 on the unit sphere, seen head-on
        expect(Number.parseFloat(probe['n·v'])).toBeCloseTo(Math.sqrt(1 - 0.3 ** 2), 3);
        expect(await page.$eval('.probe-marker', (m) => m.hidden)).toBe(false);
        for (let i = 0; i < 10; i++) await page.keyboard.press('ArrowRight');
        probe = await rows();
        expect(probe.sphere).toBe('Beckmann');
      },
    ],
  ],
  'f0-tables': [
    [
      'a row of the F0 tables is selected by Enter and keeps the focus',
      async (page) => {
        await page.focus('tr[data-material="copper"]');
        await page.keyboard.press('Enter');
        await untilIdle(page); // the live region speaks once changes settle (a pause in the app's pending work)
        expect((await getState(page, 'f0-tables')).selected).toBe('copper');
        expect(await page.evaluate(() => document.activeElement.dataset.material)).toBe('copper');
        expect(await page.$eval('.widget-live', (el) => el.textContent)).toMatch(
          /Copper, a metal; F\(0°\) linear 0\.95, 0\.64, 0\.54/,
        );
      },
    ],
  ],
};

/** No console error, no page error and no violation of the policy so far. */
const expectClean = async (page) => {
  expect(page.errors).toEqual([]);
  expect(await page.evaluate(() => window.__csp ?? [])).toEqual([]);
};

describe('every widget on a page of its own: its words, Tab, its keyboard and its numbers', () => {
  for (const name of Object.keys(WIDGETS)) {
    describe(name, () => {
      let page;
      beforeAll(async () => {
        page = await openWidget(`${name}${QUICK[name] ?? ''}`);
      });
      afterAll(async () => {
        await page?.close();
      });
      if (AXE_WIDGETS.includes(name)) {
        it('runs under the policy with no violation, and axe-core (WCAG 2.2 A and AA) finds no violation', async () => {
          expect(await axeViolations(page)).toEqual([]);
          await expectClean(page);
        });
      }
      const words = 'describes its canvases, says something new when its state changes, and Tab reaches every control';
      it(words, async () => {
        await checkWordsAndTab(page, name);
        await expectClean(page);
      });
      for (const [title, check] of MORE[name] ?? []) {
        it(title, async () => {
          await check(page);
          await expectClean(page);
        });
      }
    });
  }
});
