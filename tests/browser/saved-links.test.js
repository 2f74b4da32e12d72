// The links saved from b048b6b (tests/support/saved-links.json) of each widget whose state names changed, opened in
// this build's embed.html: the widget's state read from the test hooks is the state that build opened the link at,
// renamed (tests/support/saved-links.js); and for two explorers the spheres drawn from the old link are the very
// pixels drawn from the link this build writes for that state. A chapter page's link of the same view gives its
// widget the very state its share link gives (tests/unit/saved-links.test.js, from the page's HTML): its page is
// not opened here (rendering.html mounts two path-traced labs, the heaviest mounts of this file).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, baseUrl, getState, launchBrowser, open, shot, untilIdle, untilLoaded } from './helpers.js';
import { stateToParams } from '../../src/core/framework/state.js';
import { WIDGETS } from '../../src/widgets/registry.js';
import { RENAMED_KEYS, RENAMED_OPTIONS, SAVED, renamed } from '../support/saved-links.js';

const CHANGED = new Set([...Object.keys(RENAMED_KEYS), ...Object.keys(RENAMED_OPTIONS)]);
const LINKS = SAVED.links.filter((l) => CHANGED.has(l.widget) && l.form === 'share' && l.what !== 'defaults');
const QUICK = { maxSamples: 4 }; // the lab's reference need not converge for its state to be read
const schemaOf = async (name) => (await WIDGETS[name].load()).widget.schema;

let browser;
/** One page for every link (its draw counter and sample cap are set again at each load). */
let linkPage;
beforeAll(async () => {
  browser = await launchBrowser();
  linkPage = await open(browser, 'about:blank', QUICK);
});
afterAll(async () => {
  await browser?.close();
});

describe('a link saved from b048b6b, opened in this build', () => {
  for (const saved of LINKS) {
    it(`${saved.widget} (${saved.what}, ${saved.form}): the same state, no notice, no error`, async () => {
      const page = linkPage;
      // the last link's page left first: what it still fetched is cut off then, not counted against this link
      await page.goto('about:blank');
      page.errors.length = 0;
      await page.goto(new URL(saved.link, baseUrl()).href, { waitUntil: 'load' });
      await page.waitForFunction((k) => globalThis.__shadingLab?.widgets?.[k], { timeout: WAIT_MS }, saved.widget);
      // the widget up and drawn once (its notices shown, its errors said); the state is the claim, so its views need
      // not finish refining
      await untilLoaded(page);
      const state = await getState(page, saved.widget);
      for (const [k, v] of Object.entries(renamed(saved.widget, saved.state))) expect(state[k], k).toEqual(v);
      expect(await page.$$eval('.notice', (n) => n.map((x) => x.textContent.trim()).filter(Boolean))).toEqual([]);
      expect(page.errors).toEqual([]);
    }, 240_000);
  }
});

describe('the old link draws what the new link draws', () => {
  const picture = async (path) => {
    const page = await open(browser, path);
    await page.waitForSelector('.sphere-grid canvas');
    await untilIdle(page);
    const png = await shot(page, '.sphere-grid canvas');
    expect(page.errors).toEqual([]);
    await page.close();
    return png;
  };
  for (const name of ['ndf-explorer', 'diffuse-explorer']) {
    it(`${name}: the spheres of its by-hand link, old names against the names written now`, async () => {
      const saved = SAVED.links.find((l) => l.widget === name && l.what === 'by hand 1' && l.form === 'share');
      const schema = await schemaOf(name);
      const params = stateToParams(schema, renamed(name, saved.state));
      const now = `embed.html?${new URLSearchParams([['w', name], ...params])}`;
      expect(now).not.toBe(saved.link); // the names differ …
      expect(await picture(saved.link)).toBe(await picture(now)); // … the pixels do not
    }, 240_000);
  }
});
