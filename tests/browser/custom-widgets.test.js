// User-written terms (issue 13) in the material lab, ndf-explorer, visibility-explorer and diffuse-explorer, in a
// real Chromium: code typed into the editor as a user types it, drawn as the term predicts (the truth: closed
// forms and the JS terms of src/math), a compile error keeping the last picture, and the URL carrying the code.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  WAIT_MS,
  getState,
  launchBrowser,
  open,
  shot,
  typeCode,
  untilIdle,
  widget,
  widgetLoaded,
  withPixels,
} from './helpers.js';
import { stateToParams } from '../../src/core/framework/state.js';
import { srgbToLinear } from '../../src/math/color.js';
import { schema as labSchema } from '../../src/widgets/material-lab/schema.js';
import { schema as ndfSchema } from '../../src/widgets/ndf-explorer/schema.js';
import { schema as visibilitySchema } from '../../src/widgets/visibility-explorer/schema.js';
import { schema as diffuseSchema } from '../../src/widgets/diffuse-explorer/schema.js';
import { ANGLES as NDF_ANGLES } from '../../src/widgets/ndf-explorer/model.js';
import { matchNdfWidths } from '../../src/math/ndf-width.js';
import { ndfGGX } from '../../src/math/ndf.js';

// typed code compiled in software WebGL, and the lab's reference converged: over 60 s under a load average of 27

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

const panelText = (page, slot, selector) =>
  page.$eval(`.custom-panel[data-slot="${slot}"] ${selector}`, (el) => el.textContent);

/**
 * Opens `w` alone (embed.html) and waits for its editor. A window just wider than the phone layout (760 px), tall
 * enough to hold the widget and its editor in view; `maxSamples` caps the lab's reference (debug-hooks.js).
 * `{ drawn: false }`, for a page whose state is read and not its pictures: the small window, the reference at its
 * first batch, and a wait for it to have loaded, not to idle.
 */
async function openWidget(key, query, { maxSamples, drawn = true } = {}) {
  const size = drawn ? { width: 800, height: 1400, maxSamples } : { maxSamples: 8 };
  const page = await open(browser, `embed.html?w=${key}&${query}`, size);
  await (drawn ? widget : widgetLoaded)(page, key);
  if (!drawn) return page;
  await page.waitForSelector('.custom-panel .cm-content', { timeout: WAIT_MS });
  await untilIdle(page);
  return page;
}

/** Pages kept for the cases after the one that opened them, by widget and query; closed as each describe ends. */
const kept = new Map();
/**
 * openWidget's page, opened once for the cases of a describe that type into the same widget (a page load compiles
 * the widget's programs again). Opened by the first case that asks, so that each still runs alone (-t).
 */
function keptWidget(key, query, options) {
  if (!kept.has(`${key}?${query}`)) kept.set(`${key}?${query}`, openWidget(key, query, options));
  return kept.get(`${key}?${query}`);
}
async function closeKept() {
  const pages = await Promise.all(kept.values());
  kept.clear();
  await Promise.all(pages.map((page) => page.close()));
}

/**
 * The sphere grid's first and last cells compared: the largest channel difference (0–255) over the pixels of the
 * spheres side by side, and the mean red of each (a blank cell is not a match).
 */
async function firstAndLastCells(page, count) {
  const png = await shot(page, '.sphere-grid canvas');
  return withPixels(
    page,
    png,
    `(image) => {
      const w = image.width / ${count};
      const side = Math.min(w, image.height);
      let worst = 0, first = 0, last = 0, n = 0;
      // inside the sphere only, clear of the labels at its foot (the save button sits in a corner)
      const inside = (x, y) => (x - side / 2) ** 2 + (y - side / 2) ** 2 < (0.38 * side) ** 2;
      for (let y = 0; y < side; y++)
        for (let x = 0; x < side; x++) {
          if (!inside(x, y)) continue;
          const row = Math.floor(y + (image.height - side) / 2);
          const at = (cell) => (row * image.width + Math.floor(cell * w + (w - side) / 2 + x)) * 4;
          const [a, b] = [at(0), at(${count - 1})];
          for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(image.data[a + c] - image.data[b + c]));
          first += image.data[a]; last += image.data[b]; n++;
        }
      return { worst, first: first / n, last: last / n };
    }`,
  );
}

/** The mean red of the last of two sphere cells; polled for (POLL) where a sphere's program is rebuilt. */
const lastCellRed = async (page) => (await firstAndLastCells(page, 2)).last;
const POLL = { timeout: WAIT_MS, interval: 500 };

/**
 * On the describe's kept page, set to `state` first: types `fn { body; }` (its value `expected` where `read` reads
 * it), then the same with an undeclared name on line 2: the compiler's error lands on line 2 and `read` still reads
 * the good code's value; then the state, through the URL of the share link, opens the same code in a new page.
 */
async function compileErrorAndUrl({ key, query, state: set, slot, codeKey, schema, fn, body, read, expected }) {
  const page = await keptWidget(key, query);
  if (set) {
    await page.evaluate((k, s) => globalThis.__shadingLab.widgets[k].update(s), key, set);
    await untilIdle(page);
  }
  await typeCode(page, slot, `${fn} {\n${body};\n}`);
  expect((await read(page)) / expected).toBeCloseTo(1, 5);
  await typeCode(page, slot, `${fn} {\n${body} * missing;\n}`);
  expect(await panelText(page, slot, '.custom-problems')).toMatch(/^Line 2: .*missing/);
  expect(await panelText(page, slot, '.custom-status')).toMatch(/keeps your last good code/);
  expect((await read(page)) / expected).toBeCloseTo(1, 5);
  const state = await getState(page, key);
  const again = await openWidget(key, stateToParams(schema, state).toString(), { drawn: false });
  expect((await getState(again, key))[codeKey]).toBe(state[codeKey]);
  expect([...page.errors, ...again.errors]).toEqual([]);
  await again.close();
}

/** Float32 agreement, the parity harness's tolerance: |Δ| ≤ 1e-5 + 1e-4 |reference|. */
const withinFloat32 = (value, reference) => Math.abs(value - reference) <= 1e-5 + 1e-4 * Math.abs(reference);

describe('ndf-explorer: your D beside the five', () => {
  afterAll(closeKept);
  const QUERY = 'D=ggx,custom&hwhm=8';
  const alpha = matchNdfWidths(8, {}).ggx.alpha;
  const jsGgx = Array.from(NDF_ANGLES, (deg) => ndfGGX(Math.cos((deg * Math.PI) / 180), alpha));
  const curves = (page) => page.evaluate(() => globalThis.__shadingLab.widgets['ndf-explorer'].getCurves());
  const integrals = (page) => page.evaluate(() => globalThis.__shadingLab.widgets['ndf-explorer'].getIntegrals());

  it('the starter draws ndfGGX’s curve at the matched α (float32) and GGX’s sphere; 2 × GGX doubles both', async () => {
    const page = await keptWidget('ndf-explorer', QUERY); // the starter first: read before any case types
    const start = await curves(page);
    start.custom.forEach((d, i) => expect(withinFloat32(d, jsGgx[i])).toBe(true));
    expect((await integrals(page)).custom).toBeCloseTo(1, 4);
    const spheres = await firstAndLastCells(page, 2);
    expect(spheres.worst).toBeLessThanOrEqual(2);
    expect(spheres.last).toBeGreaterThan(5);
    await typeCode(
      page,
      'D',
      `float customD(float nh, float alpha) {
float a2 = alpha * alpha;
float d = nh * nh * (a2 - 1.0) + 1.0;
return 2.0 * a2 / (PI * d * d);
}`,
    );
    const doubled = await curves(page);
    doubled.custom.forEach((d, i) => expect(withinFloat32(d, 2 * jsGgx[i])).toBe(true));
    expect((await integrals(page)).custom).toBeCloseTo(2, 3);
    // the sphere's program is rebuilt with the new code after the plots have read it
    await expect.poll(() => lastCellRed(page), POLL).toBeGreaterThan(spheres.last * 1.2);
    expect(page.errors).toEqual([]);
  });

  it('a compile error names the user’s line and keeps the curve; the URL carries the code', () =>
    compileErrorAndUrl({
      key: 'ndf-explorer',
      query: QUERY,
      slot: 'D',
      codeKey: 'codeD',
      schema: ndfSchema,
      fn: 'float customD(float nh, float alpha)',
      body: 'return 3.0 * alpha',
      read: async (page) => (await curves(page)).custom[0],
      expected: 3 * alpha,
    }));
});

describe('material lab: your whole BRDF', () => {
  afterAll(closeKept);
  const EXTENT = 1.1; // the lab's view half width (src/lab/lab-uniforms.js)
  const RES = 192; // the lab's image size (material-lab.js)
  const POINTS = [
    [0, 0],
    [0.5, 0.1],
    [-0.4, 0.5],
    [0.1, -0.8],
  ];
  const texelOf = ([x, y]) => [x, y].map((c) => Math.floor((c / (2 * EXTENT) + 0.5) * RES));
  /** The approximation's red channel at POINTS (the sphere coordinates' texels). */
  const approxAt = (page) =>
    page.evaluate(
      (texels, res) => {
        const image = globalThis.__shadingLab.widgets['material-lab'].read('approx');
        return texels.map(([i, j]) => image[(j * res + i) * 4]);
      },
      POINTS.map(texelOf),
      RES,
    );
  /** n·l at each point's texel centre for a light from the viewer (lightTheta 0): n = (x, y, √(1 − x² − y²)), l = z. */
  const cosines = POINTS.map(texelOf).map((texel) => {
    const [x, y] = texel.map((i) => ((2 * (i + 0.5)) / RES - 1) * EXTENT);
    return Math.sqrt(1 - x * x - y * y);
  });
  // the sphere's grey, as the lab's sRGB colour field holds it, and its linear value: Lambert's albedo ρ
  const GREY = '#8c8c8c';
  const rho = srgbToLinear(0x8c / 255);
  const lambertCode = `vec3 customBRDF(vec3 l, vec3 v) {
return vec3(${rho.toFixed(7)} / PI);
}`;
  const LIGHT = 'punctual=1&lightTheta=0&lightPhi=0&cLight=1&env=0&refSamples=128';
  // under the punctual light alone the reference is exact from its first batch (lab-reference.glsl), and these
  // tests read the approximation: the reference stops at one batch of 8 samples instead of converging for nothing
  const FIRST_BATCH = { maxSamples: 8 };

  it('ρ/π typed in renders π f (n·l) = ρ (n·l) under the punctual light, as the lab’s Lambert sphere', async () => {
    const page = await keptWidget('material-lab', `brdfSource=custom&${LIGHT}`, FIRST_BATCH);
    await typeCode(page, 'brdf', lambertCode);
    expect((await getState(page, 'material-lab')).codeBRDF).toContain(rho.toFixed(7));
    const custom = await approxAt(page);
    custom.forEach((value, i) => expect(value / (rho * cosines[i])).toBeCloseTo(1, 2)); // half-float target
    // the lab's own Lambert sphere (diffuse layer only), same colour
    await page.evaluate(
      (grey) =>
        globalThis.__shadingLab.widgets['material-lab'].update({
          brdfSource: 'model',
          layers: 'diffuse',
          diffuse: 'lambert',
          cdiff: grey,
        }),
      GREY,
    );
    await untilIdle(page);
    const lambert = await approxAt(page);
    lambert.forEach((value, i) => expect(value / custom[i]).toBeCloseTo(1, 3));
    expect(page.errors).toEqual([]);
  });

  it('a compile error names the user’s line and keeps the last picture; the URL carries the code', async () => {
    const page = await keptWidget('material-lab', `brdfSource=custom&${LIGHT}`, FIRST_BATCH);
    // the user's BRDF shown (the case before switches the kept page to the lab's Lambert)
    await page.evaluate(() => globalThis.__shadingLab.widgets['material-lab'].update({ brdfSource: 'custom' }));
    await typeCode(page, 'brdf', 'vec3 customBRDF(vec3 l, vec3 v) {\nreturn vec3(0.5 / PI);\n}');
    const before = await approxAt(page);
    before.forEach((value, i) => expect(value / (0.5 * cosines[i])).toBeCloseTo(1, 2));
    // an undeclared name on line 2: parses, and the GLSL compiler refuses it there
    await typeCode(page, 'brdf', 'vec3 customBRDF(vec3 l, vec3 v) {\nreturn vec3(0.9 / PI) * missing;\n}');
    expect(await panelText(page, 'brdf', '.custom-problems')).toMatch(/^Line 2: .*missing/);
    expect(await panelText(page, 'brdf', '.custom-status')).toMatch(/keeps your last good code/);
    expect(await approxAt(page)).toEqual(before);
    // the code as the share link carries it, opened in a new page: the same state
    const state = await getState(page, 'material-lab');
    const query = stateToParams(labSchema, state).toString();
    const again = await openWidget('material-lab', query, { drawn: false });
    expect((await getState(again, 'material-lab')).codeBRDF).toBe(state.codeBRDF);
    expect(page.errors).toEqual([]);
    expect(again.errors).toEqual([]);
    await again.close();
  });

  it('in the white furnace the Monte Carlo reference of ρ/π converges to the albedo ρ (GGX + cosine)', async () => {
    // the kept page, the user's BRDF in the furnace: its reference stops at one batch (the cap is read at each frame,
    // debug-hooks.js sampleTarget), not converged for nothing; then the typed code's reference gets SAMPLES
    const page = await keptWidget('material-lab', `brdfSource=custom&${LIGHT}`, FIRST_BATCH);
    await page.evaluate(() =>
      globalThis.__shadingLab.widgets['material-lab'].update({
        brdfSource: 'custom',
        punctual: false,
        env: true,
        environment: 'furnace',
        envMethod: 'importance',
      }),
    );
    await untilIdle(page);
    // 64 samples a texel, and the mean of the 13 × 13 texels around each point (in the furnace every texel's
    // value is ρ): its standard error was 0.06–0.12 % of ρ (against 0.18–0.38 % for 5 × 5 texels at 128 samples), so
    // a bias of 1 % of ρ shows at 8 standard errors or more; the bound on it below says the precision was reached
    const SAMPLES = 64;
    await page.evaluate((n) => (globalThis.__shadingLab.maxSamples = n), SAMPLES);
    await typeCode(page, 'brdf', lambertCode);
    await page.waitForFunction(
      () => {
        const p = globalThis.__shadingLab.widgets['material-lab'].getProgress();
        return p.frame >= p.target;
      },
      { timeout: WAIT_MS, polling: 500 },
    );
    expect(await page.evaluate(() => globalThis.__shadingLab.widgets['material-lab'].getProgress())).toEqual({
      frame: SAMPLES,
      target: SAMPLES,
    });
    // per point, the mean of the 13 × 13 texels around it and its standard error (Monte Carlo noise)
    const reference = await page.evaluate(
      (texels, res) => {
        const image = globalThis.__shadingLab.widgets['material-lab'].read('reference');
        return texels.map(([i, j]) => {
          const x = [];
          for (let dj = -6; dj <= 6; dj++)
            for (let di = -6; di <= 6; di++) x.push(image[((j + dj) * res + i + di) * 4]);
          const mean = x.reduce((a, b) => a + b) / x.length;
          return { mean, se: Math.sqrt(x.reduce((a, b) => a + (b - mean) ** 2, 0) / (x.length - 1) / x.length) };
        });
      },
      POINTS.map(texelOf),
      RES,
    );
    reference.forEach(({ mean, se }) => {
      expect(se).toBeLessThan(0.0025 * rho);
      expect(Math.abs(mean - rho)).toBeLessThan(4 * se + 1e-3 * rho);
    });
    expect(page.errors).toEqual([]);
  });
});

describe('visibility-explorer: your V beside the catalogue’s', () => {
  afterAll(closeKept);
  const QUERY = 'V=smithGGXCorrelated,implicit,custom&alpha=0.5&config=view-fixed&viewTheta=60';
  const curves = (page) => page.evaluate(() => globalThis.__shadingLab.widgets['visibility-explorer'].getCurves());

  it('the starter draws height-correlated Smith’s JS curve and sphere; V = 1 typed draws the implicit G', async () => {
    const page = await keptWidget('visibility-explorer', QUERY);
    const start = await curves(page);
    start.custom.forEach((g, i) => expect(withinFloat32(g, start.smithGGXCorrelated[i])).toBe(true));
    const spheres = await firstAndLastCells(page, 3);
    expect(spheres.worst).toBeLessThanOrEqual(2);
    expect(spheres.last).toBeGreaterThan(5);
    await typeCode(page, 'V', 'float customV(float nl, float nv, float alpha) {\nreturn 1.0;\n}');
    const implicit = await curves(page);
    implicit.custom.forEach((g, i) => expect(withinFloat32(g, implicit.implicit[i])).toBe(true));
    expect(page.errors).toEqual([]);
  });

  it('a compile error names the user’s line and keeps the curve; the URL carries the code', () =>
    compileErrorAndUrl({
      key: 'visibility-explorer',
      query: QUERY,
      state: { config: 'mirror' },
      slot: 'V',
      codeKey: 'codeV',
      schema: visibilitySchema,
      fn: 'float customV(float nl, float nv, float alpha)',
      body: 'return 0.5 / (nl * nv)',
      read: async (page) => (await curves(page)).custom[0], // G at 0°: 0.5
      expected: 0.5,
    }));
});

describe('diffuse-explorer: your diffuse term beside the catalogue’s', () => {
  afterAll(closeKept);
  const QUERY = 'models=lambert,custom&sigma=30&cdiff=0.8&lightTheta=40&lightPhi=0';
  /** The profile plot's series by model, as uPlot holds them. */
  const profiles = async (page) => {
    const [, lambert, custom] = await page.evaluate(
      () => globalThis.__shadingLab.widgets['diffuse-explorer'].getPlots().profile,
    );
    return { lambert, custom };
  };

  it('the starter draws Lambert’s JS profile and sphere; (1 + α) Lambert reads α as σ in radians', async () => {
    const page = await keptWidget('diffuse-explorer', QUERY);
    const start = await profiles(page);
    start.custom.forEach((y, i) => expect(withinFloat32(y, start.lambert[i])).toBe(true));
    const spheres = await firstAndLastCells(page, 2);
    expect(spheres.worst).toBeLessThanOrEqual(2);
    expect(spheres.last).toBeGreaterThan(5);
    await typeCode(
      page,
      'diffuse',
      'vec3 customDiffuse(vec3 cdiff, vec3 l, vec3 v, float alpha) {\n' +
        'if (!(l.z > 0.0 && v.z > 0.0)) return vec3(0.0);\nreturn cdiff / PI * (1.0 + alpha);\n}',
    );
    const scaled = await profiles(page);
    const factor = 1 + (30 * Math.PI) / 180; // σ = 30° in radians
    scaled.custom.forEach((y, i) => expect(withinFloat32(y, factor * scaled.lambert[i])).toBe(true));
    // 1.52 × in linear radiance is about 1.2 × in sRGB (and the brightest pixels clip). The sphere's program is
    // compiled with the new code after the plots have read it: under load that was seen to take more than the wait
    await expect.poll(() => lastCellRed(page), POLL).toBeGreaterThan(spheres.last * 1.1);
    expect(page.errors).toEqual([]);
  });

  it('a compile error names the user’s line and keeps the curve; the URL carries the code', () =>
    compileErrorAndUrl({
      key: 'diffuse-explorer',
      query: QUERY,
      state: { diffuse: ['custom'], lightTheta: 0 },
      slot: 'diffuse',
      codeKey: 'codeDiffuse',
      schema: diffuseSchema,
      fn: 'vec3 customDiffuse(vec3 cdiff, vec3 l, vec3 v, float alpha)',
      body: 'return vec3(0.25 / PI)',
      read: async (page) => (await profiles(page)).lambert[100], // the only series: Lo at the centre, 0.25 · 1
      expected: 0.25,
    }));
});
