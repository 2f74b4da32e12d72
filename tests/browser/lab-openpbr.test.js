// The material lab's OpenPBR Surface panel, in Chromium (issue 29): its groups as the specification groups them;
// with the coat and fuzz switched off, a metal of OpenPBR (F82-tint at tint 1 is Schlick) renders as the talk's
// model (Schlick, GGX, height-correlated Smith) renders the same F0 and α, pixel for pixel, through a different
// shader; the furnace figures against the independent quadrature of tests/support/openpbr-albedo.js and the split
// sum's albedo (integrate.js); each preset loads its values; a .mtlx file loaded through the button shows its values
// in the panel, a bad one is refused with a message naming what is wrong and the material kept, and what the Save
// button writes reads back to the same material; choosing OpenPBR opens its base folder (or the one last worked in);
// and the latency of a parameter change held as a slider's drag, timed as bench/latency.js times it, the reference
// and the bars waiting for the release.
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, allowDownloads, getState, launchBrowser, open, untilIdle } from './helpers.js';
import { SMALL_VIEWPORT } from './harness.js';
import { timeChange } from '../../bench/latency.js';
import { openPbrAlbedo } from '../support/openpbr-albedo.js';
import { albedoGGX } from '../../src/math/integrate.js';
import { OPENPBR_DEFAULTS } from '../../src/math/openpbr.js';
import { readMtlx, writeMtlx } from '../../src/lab/mtlx/mtlx.js';
import { OPENPBR_PRESETS } from '../../src/lab/openpbr-presets.js';
import { materialByKey } from '../../src/math/materials.js';

const QUERY = 'lab.env=0&lab.refSamples=128&lab.cLight=1';
const GOLD = materialByKey('gold').linear;
const luminance = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

let browser;
let page;
let dir;
const lab = (fn, ...args) => page.evaluate(fn, ...args);
const barsReady = () =>
  page.waitForFunction(() => globalThis.__shadingLab.widgets.lab.openpbr.ready, { timeout: WAIT_MS, polling: 200 });
/** Brings the lab's images into view: it draws only what is seen. */
const showImages = async () => {
  await page.$eval('.widget-material-lab canvas', (c) => c.scrollIntoView({ block: 'center' }));
  await untilIdle(page);
};
const material = () => lab(() => globalThis.__shadingLab.widgets.lab.openpbr.material());
const message = () => lab(() => document.querySelector('.openpbr-message').textContent);
/** Picks a file through the panel's Load button's file input, as a user would. */
async function pick(name, text) {
  const file = join(dir, name);
  writeFileSync(file, text);
  const input = await page.$('.openpbr-panel input[type=file]');
  await input.uploadFile(file);
  await page.waitForFunction((n) => document.querySelector('.openpbr-message').textContent.includes(n), {}, name);
  await untilIdle(page);
}

beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'lab-openpbr-'));
  browser = await launchBrowser();
  page = await open(browser, `rendering.html?${QUERY}`, SMALL_VIEWPORT);
  await page.waitForFunction(() => globalThis.__shadingLab?.widgets?.lab, { timeout: WAIT_MS });
  await untilIdle(page);
});
afterAll(async () => {
  await browser?.close();
});

describe('the material lab renders OpenPBR Surface', () => {
  it('its panel groups the parameters as the specification does, each group with a switch', async () => {
    const folders = await lab(() => [...document.querySelectorAll('.lil-gui .lil-title')].map((t) => t.textContent));
    for (const g of ['base', 'specular', 'coat', 'fuzz']) expect(folders).toContain(`OpenPBR ${g}`);
    const names = await lab(() => [...document.querySelectorAll('.lil-name')].map((n) => n.textContent));
    for (const key of Object.keys(OPENPBR_DEFAULTS)) expect(names).toContain(key);
    for (const layer of ['Base', 'Specular', 'Coat', 'Fuzz']) expect(names).toContain(`${layer} layer on`);
  });

  it('choosing OpenPBR opens its base folder, or the one last worked in, its controls in view', async () => {
    /** The OpenPBR folders' titles that are open, and whether `key`'s control is laid out (a closed one is not). */
    const folders = (key) =>
      lab((k) => {
        const titled = [...document.querySelectorAll('.widget-material-lab .lil-gui')].filter((f) =>
          f.querySelector(':scope > .lil-title')?.textContent.startsWith('OpenPBR'),
        );
        const open = titled.filter((f) => !f.classList.contains('lil-closed'));
        const name = [...document.querySelectorAll('.lil-name')].find((n) => n.textContent === k);
        const shown = name.closest('.lil-controller').getBoundingClientRect().height > 0;
        return { open: open.map((f) => f.querySelector(':scope > .lil-title').textContent), shown };
      }, key);
    const choose = async (brdfSource) => {
      await lab((b) => globalThis.__shadingLab.widgets.lab.update({ brdfSource: b }), brdfSource);
      await untilIdle(page);
    };
    expect(await folders('base_color')).toEqual({ open: [], shown: false }); // the lab opens with them closed
    await choose('openpbr');
    await expect
      .poll(() => folders('base_color'), { timeout: WAIT_MS })
      .toEqual({ open: ['OpenPBR base'], shown: true });
    // the user closes the base, opens the coat and works in it; back to the model, the coat closed again
    const title = (group) =>
      page.evaluateHandle((g) => [...document.querySelectorAll('.lil-title')].find((t) => t.textContent === g), group);
    await (await title('OpenPBR base')).click();
    await (await title('OpenPBR coat')).click();
    // lil-gui opens and closes a folder by a CSS transition: on a loaded machine it takes longer than expect.poll's 1 s
    await expect.poll(() => folders('coat_ior'), { timeout: WAIT_MS }).toEqual({ open: ['OpenPBR coat'], shown: true });
    await page.evaluate(() => {
      const name = [...document.querySelectorAll('.lil-name')].find((n) => n.textContent === 'coat_ior');
      name.closest('.lil-controller').querySelector('input').focus();
    });
    await choose('model');
    await (await title('OpenPBR coat')).click();
    await expect.poll(() => folders('coat_ior'), { timeout: WAIT_MS }).toEqual({ open: [], shown: false });
    await choose('openpbr');
    await expect.poll(() => folders('coat_ior'), { timeout: WAIT_MS }).toEqual({ open: ['OpenPBR coat'], shown: true });
  });

  it('coat and fuzz off: an OpenPBR metal renders as the talk’s model (Schlick, GGX, correlated Smith)', async () => {
    const model = {
      brdfSource: 'model',
      material: 'gold',
      alpha: 0.25,
      F: 'schlick',
      D: 'ggx',
      V: 'smithGGXCorrelated',
      layers: 'specular',
      compensation: 'none',
      anisotropy: 0,
    };
    await lab((s) => globalThis.__shadingLab.widgets.lab.update(s), model);
    await showImages();
    await lab(() => (globalThis.__modelImage = globalThis.__shadingLab.widgets.lab.read('approx')));
    // gold's F0 exact through a file; the coat and fuzz weighted but switched off: the switch must take them away
    const text = writeMtlx({
      base_color: GOLD,
      base_metalness: 1,
      specular_roughness: 0.5, // α = 0.25
      coat_weight: 1,
      coat_roughness: 0.1,
      fuzz_weight: 1,
    });
    await pick('gold-coated.mtlx', text);
    await showImages();
    const compare = () =>
      lab(() => {
        const a = globalThis.__modelImage;
        const b = globalThis.__shadingLab.widgets.lab.read('approx');
        let [worst, peak] = [0, 0];
        for (let i = 0; i < a.length; i += 4) {
          if (a[i + 3] < 1) continue; // off the sphere
          for (let c = 0; c < 3; c++)
            [worst, peak] = [Math.max(worst, Math.abs(a[i + c] - b[i + c])), Math.max(peak, a[i + c])];
        }
        return worst / peak;
      });
    const coated = await compare();
    expect(coated).toBeGreaterThan(0.05); // the coat and fuzz change the picture
    await lab(() => globalThis.__shadingLab.widgets.lab.update({ openpbrCoat: false, openpbrFuzz: false }));
    await showImages();
    const bare = await compare();
    console.log(`OpenPBR metal against the talk's model: worst difference ${bare.toExponential(2)} of the peak`);
    expect(bare).toBeLessThan(2e-3); // half-float images: 1e-3 relative
  });
});

describe('the furnace figures and the presets', () => {
  /** The panel's furnace figures: E head-on and at 60°, and the white stack's. */
  const furnace = async () => {
    await barsReady();
    const text = await lab(() => document.querySelector('.openpbr-bars').textContent);
    const e = [...text.matchAll(/returns E = ([\d.]+)/g)].map((m) => Number(m[1]));
    const white = [...text.matchAll(/white the stack returns ([\d.]+)/g)].map((m) => Number(m[1]));
    return { e, white };
  };

  for (const [key, preset] of Object.entries(OPENPBR_PRESETS)) {
    it(`${preset.label}: the button loads its values; E against the quadrature of openPbrLayers`, async () => {
      await page.click(`.openpbr-preset-${key}`);
      await untilIdle(page);
      const m = await material();
      for (const [k, v] of Object.entries({ ...OPENPBR_DEFAULTS, ...preset.material })) expect(m[k]).toEqual(v);
      expect((await getState(page, 'lab')).brdfSource).toBe('openpbr');
      // the quadrature's lobes are isotropic: a stretched one (brushed aluminium) is measured unstretched
      if (m.specular_roughness_anisotropy) {
        await lab(() => globalThis.__shadingLab.widgets.lab.update({ specular_roughness_anisotropy: 0 }));
      }
      const { e, white } = await furnace();
      [1, 0.5].forEach((mu, i) => {
        const truth = luminance(openPbrAlbedo({ ...m, specular_roughness_anisotropy: 0 }, mu, 24).total);
        expect(Math.abs(e[i] - truth), `E(${mu}) ${e[i]} against ${truth}`).toBeLessThan(4e-3);
      });
      if (key === 'gold') {
        // gold with every colour white is a white GGX metal: the split sum's albedo, computed apart
        [1, 0.5].forEach((mu, i) => expect(Math.abs(white[i] - albedoGGX(mu, 0.25 ** 2))).toBeLessThan(4e-3));
      }
    });
  }
});

describe('MaterialX files through the lab’s buttons', () => {
  const file = writeMtlx(
    { base_color: [0.1, 0.6, 0.9], coat_weight: 1, coat_roughness: 0.125, specular_ior: 1.6 },
    'paint_from_file',
  );

  it('a file loaded shows its values in the panel; a bad one is refused by name and the material kept', async () => {
    await pick('paint.mtlx', file);
    const shown = await lab(() =>
      Object.fromEntries(
        [...document.querySelectorAll('.lil-controller')].map((c) => [
          c.querySelector('.lil-name')?.textContent,
          c.querySelector('input')?.value,
        ]),
      ),
    );
    expect(Number(shown.coat_roughness)).toBe(0.125);
    expect(Number(shown.specular_ior)).toBe(1.6);
    expect((await material()).base_color).toEqual([0.1, 0.6, 0.9]);
    const before = await getState(page, 'lab');
    const textured = file.replace(
      '<input name="coat_roughness" type="float" value="0.125" />',
      '<input name="coat_roughness" type="float" nodename="noise1" />',
    );
    await pick('textured.mtlx', textured);
    expect(await message()).toContain('coat_roughness');
    expect(await message()).toContain('noise1');
    await pick('image.mtlx', file.replace('</materialx>', '<image name="tex1" type="color3" /></materialx>'));
    expect(await message()).toMatch(/<image> “tex1”/);
    await pick('deep.mtlx', `<materialx version="1.39">${'<a>'.repeat(40)}${'</a>'.repeat(40)}</materialx>`);
    expect(await message()).toContain('deep.mtlx');
    expect(await getState(page, 'lab')).toEqual(before);
    expect(await message()).toContain('kept');
  });

  it('Save writes the material; reading it back gives the loaded material exactly', async () => {
    await pick('paint.mtlx', file);
    await allowDownloads(page, dir);
    await page.click('.openpbr-save');
    await page.waitForFunction(() => document.querySelector('.openpbr-message').textContent.startsWith('Saved'));
    const download = () => readdirSync(dir).find((f) => f.startsWith('paint_from_file') && f.endsWith('.mtlx'));
    await expect.poll(download, { timeout: WAIT_MS }).toBeTruthy(); // the browser writes it after the click
    const saved = download();
    const text = readFileSync(join(dir, saved), 'utf8');
    expect(readMtlx(text).material).toEqual(readMtlx(file).material);
  });
});

describe('latency', () => {
  it('a change held reaches its frame, the reference waiting for the release (bench/latency.js timing)', async () => {
    await page.click('.openpbr-preset-carPaint');
    await showImages();
    // does a change go through the render loop? (bench/latency.js asks the same before it times a widget)
    const before = await lab(() => globalThis.__shadingLab.frames);
    await lab(() => globalThis.__shadingLab.widgets.lab.update({ specular_roughness: 0.5 }));
    await untilIdle(page);
    const viaLoop = (await lab(() => globalThis.__shadingLab.frames)) > before;
    const values = Array.from({ length: 12 }, (_, i) => 0.2 + 0.04 * i);
    const ms = [];
    const pointer = (type) =>
      page.$eval('.widget-material-lab', (w, t) => w.dispatchEvent(new PointerEvent(t, { bubbles: true })), type);
    await pointer('pointerdown'); // held, as on a slider's drag (bench/latency.js)
    for (const v of values) ms.push(await page.evaluate(timeChange, 'lab', 'specular_roughness', v, viaLoop));
    // held: the reference (the whole stack, a batch of samples of every light per pixel) and the bars wait, and the
    // captions say so; released, the reference starts over for the last value and the bars show it
    const stats = () => lab(() => globalThis.__shadingLab.widgets.lab.getStats());
    const captions = () => lab(() => document.querySelector('.widget-material-lab .lab-captions').textContent);
    expect((await stats()).waiting).toBe(true);
    expect(await captions()).toContain('the one before the drag');
    expect(await lab(() => globalThis.__shadingLab.widgets.lab.openpbr.ready)).toBe(false);
    await pointer('pointerup');
    await expect.poll(async () => (await stats()).waiting, { timeout: WAIT_MS }).toBe(false);
    expect(await captions()).toMatch(/Reference: Monte Carlo, \d+ of \d+ samples/);
    await barsReady();
    expect((await material()).specular_roughness).toBe(values.at(-1));
    const sorted = ms.filter((x) => x !== null).sort((a, b) => a - b);
    const median = sorted[Math.floor(sorted.length / 2)];
    const load = (await import('node:os')).loadavg()[0].toFixed(1);
    console.log(
      `OpenPBR lab, specular_roughness: median ${median.toFixed(1)} ms, worst ${sorted.at(-1).toFixed(1)} ms ` +
        `(target 50 ms; load average ${load}, software GL)`,
    );
    // every change drew its frame; the figure against the 50 ms target is the bench's to judge on an idle machine
    // (bench/latency.js), not a shared one's: printed here
    expect(sorted.length).toBe(values.length);
  });
});
