// npm run bench:latency [-- --widget NAME …]: for every widget, the time from a state change to the changed frame, over
// a scripted drag (a slider swept in small steps, one change after the previous frame is done, a pointer held on the
// widget meanwhile as on a slider: framework/held-input.js): median and worst. "Done" is: the render loop's next
// animation frame has run (it draws what changed), every canvas of the widget has finished its GPU work (a one-pixel
// read-back), and the browser reached the following frame. A widget that keeps drawing a second after the drag (a Monte
// Carlo reference converging) is progressive and is reported apart: its number is the time to its first changed frame.
// Writes bench/results/latency.json; `npm run bench` runs the same part (measureLatency) into
// bench/results/latest.json.
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { WIDGETS } from '../src/widgets/registry.js';
import { ROOT, openPage, settle } from '../tests/browser/harness.js';
import { buildTemporaryApp, inBrowser } from './browser-part.js';

const STEPS = 24;
// The pauses (ms) after the widget opens, after the change that tells whether it draws through the render loop, and
// after the drag (a widget that draws more than two frames in it is progressive)
const PAUSES = { open: 1500, probe: 1500, after: 1000 };
// --quick (the bench's test): only that the part runs, on a 2-D widget and one drawn by the render loop, with short
// pauses (its figures and its progressive flags are not read)
const QUICK = { steps: 3, widgets: ['fresnel-curves', 'fresnel-zones'], pauses: { open: 300, probe: 300, after: 300 } };
export const TARGET_MS = 50;
// State each widget opens in: fewer path-traced samples for software rendering (as the browser tests do); the
// zones of l·h for fresnel-zones, whose light (the dragged control) plays no part in its modes of n·v.
const LIGHT_STATE = {
  'fresnel-zones': '&mode=zones-lh',
  media: '&samples=16',
  'material-lab': '&refSamples=128',
  'lighting-models': '&refSamples=128',
};

/**
 * The control a user would drag, per widget: [key, from, to] (a number swept in STEPS steps) or [key, [values]],
 * optionally with a state to open in ('&key=value…', e.g. an anisotropy that the azimuths need to matter); a widget
 * with several controls worth timing has a list of them, one row each. The key must be one the widget's schema has
 * and its views read. A new widget adds its row (the bench stops on a widget without one).
 */
const DRAGS = {
  'fresnel-curves': ['ior', 1.2, 2.4],
  'fresnel-zones': ['lightTheta', 20, 120],
  'f0-tables': [
    'selected',
    ['gold', 'silver', 'copper', 'iron', 'aluminum', 'water', 'glass-low', 'plastic-high', 'glass-high', 'diamond'],
  ],
  media: ['distance', -2, 1],
  surfaces: ['theta', 10, 70],
  'subsurface-scale': ['sigmaS', 1, 10],
  radiance: ['distance', 0.5, 10],
  'brdf-lobe': [
    ['lightTheta', 10, 70],
    ['lightPhi', 0, 180, '&anisotropy=0.6'], // past the talk (issue 28): the light's and the view's azimuths
    ['viewPhi', -90, 90, '&anisotropy=0.6'],
  ],
  'measured-brdf': ['lightTheta', 10, 70],
  'ndf-explorer': [
    ['hwhm', 5, 25],
    ['anisotropy', 0, 0.9],
  ],
  'visibility-explorer': [
    ['alpha', 0.1, 0.8],
    ['anisotropy', 0, 0.9], // its G1 against azimuth
  ],
  'anisotropic-microsurface': [
    ['theta', 30, 85],
    ['alphaX', 0.2, 1], // the roughness along t: its anisotropy
  ],
  microfacets: ['alpha', 0.2, 0.8],
  energy: ['metalAlpha', 0.2, 1], // its one slider: the coloured metal's roughness
  'diffuse-explorer': ['lightTheta', 10, 70],
  'material-lab': [
    ['lightTheta', 10, 70],
    ['anisotropy', 0.05, 0.9],
  ],
  'lighting-models': ['alpha', 0.2, 0.6],
};

/** Work a widget starts when opened and ends by itself (off the main thread): the drag waits until it is done. */
const OPENING_WORK = {
  'measured-brdf': () => Object.keys(globalThis.__shadingLab.widgets['measured-brdf'].getFits()).length === 5,
};

/** The drags of a widget: [[key, from, to, openWith?] …] (a single drag as a list of one). */
function dragsOf(name) {
  const drags = DRAGS[name];
  if (!drags) throw new Error(`bench/latency.js: add the drag of ${name} to DRAGS`);
  return Array.isArray(drags[0]) ? drags : [drags];
}

async function dragValues(name, [key, from, to], steps) {
  const { schema } = await import(`../src/widgets/${name}/schema.js`);
  if (!schema[key]) throw new Error(`bench/latency.js: ${name} has no state key ${key} (its schema changed?)`);
  const values = Array.isArray(from)
    ? Array.from({ length: steps }, (_, i) => from[i % from.length])
    : Array.from({ length: steps }, (_, i) => from + ((to - from) * i) / (steps - 1));
  return { key, values, step: schema[key].step ?? 0 };
}

/**
 * In the page: one change, timed to its finished frame (ms). With `viaLoop`, the frame is the render loop's next
 * draw (it may come frames later, after work off the main thread); otherwise the next animation frame.
 */
export function timeChange(name, key, value, viaLoop) {
  const NO_FRAME_MS = 5000;
  const lab = globalThis.__shadingLab;
  const frame = () => new Promise((r) => requestAnimationFrame(r));
  const drawn = async (before) => {
    while (viaLoop && lab.frames === before && performance.now() - t0 < NO_FRAME_MS) await frame();
    if (!viaLoop) await frame();
    return lab.frames !== before || !viaLoop;
  };
  const before = lab.frames;
  const t0 = performance.now();
  lab.widgets[name].update({ [key]: value });
  return drawn(before).then((changed) => {
    if (!changed) return null; // the value was the same after rounding to the control's step: nothing to draw
    for (const canvas of document.querySelectorAll('.widget canvas')) {
      const gl = canvas.getContext('webgl2');
      if (gl && !gl.isContextLost()) gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    }
    return frame().then(() => performance.now() - t0);
  });
}

const quantile = (xs, q) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];

/** The widget's state takes the dragged value (to the control's step): else the drag would time nothing. */
async function checkTaken(page, name, { key, step }, value) {
  const now = await page.evaluate((n, k) => globalThis.__shadingLab.widgets[n].getState()[k], name, key);
  const taken = typeof value === 'number' ? Math.abs(now - value) <= step / 2 + 1e-9 : now === value;
  if (!taken) throw new Error(`bench/latency.js: ${name}.update({ ${key}: ${value} }) left ${key} at ${now}`);
}

/**
 * One widget's row for one drag `spec` of DRAGS; `variant` ({ query, drag(steps) }: bench/openpbr-latency.js) opens
 * it in another state, with a drag of its own, instead. `pauses`: see PAUSES.
 */
export async function measure(browser, url, name, spec, steps, variant = null, pauses = PAUSES) {
  const drag = variant ? await variant.drag(steps) : await dragValues(name, spec, steps);
  const { key, values } = drag;
  const openWith = !variant && typeof spec.at(-1) === 'string' ? spec.at(-1) : '';
  const path = `embed.html?w=${name}${variant?.query ?? LIGHT_STATE[name] ?? ''}${openWith}`;
  const page = await openPage(browser, url, path, { width: 1280, height: 2600 });
  await page.waitForFunction((n) => globalThis.__shadingLab?.widgets?.[n], { timeout: 60_000 }, name);
  if (OPENING_WORK[name]) await page.waitForFunction(OPENING_WORK[name], { timeout: 300_000, polling: 500 });
  await settle(page, pauses.open);
  // does a change go through the render loop (a 3-D view)? then each change waits for its draw
  const before = await page.evaluate(() => globalThis.__shadingLab.frames);
  await page.evaluate((n, k, v) => globalThis.__shadingLab.widgets[n].update({ [k]: v }), name, key, values.at(-1));
  await checkTaken(page, name, drag, values.at(-1));
  await settle(page, pauses.probe);
  const viaLoop = (await page.evaluate(() => globalThis.__shadingLab.frames)) > before;
  let ms = [];
  const pointer = (type) =>
    page.$eval('.widget', (w, t) => w.dispatchEvent(new PointerEvent(t, { bubbles: true })), type);
  await pointer('pointerdown'); // a drag's frames, drawn as during one (the 3-D views of meshes: not multisampled)
  for (const v of values) ms.push(await page.evaluate(timeChange, name, key, v, viaLoop));
  await pointer('pointerup');
  ms = ms.filter((x) => x !== null);
  const after = await page.evaluate(() => globalThis.__shadingLab.frames);
  await settle(page, pauses.after);
  const progressive = (await page.evaluate(() => globalThis.__shadingLab.frames)) - after > 2;
  if (page.errors.length) throw new Error(`${name}: ${page.errors.join('\n')}`);
  await page.close();
  return { widget: name, key, steps: ms.length, medianMs: quantile(ms, 0.5), worstMs: Math.max(...ms), progressive };
}

const rowText = (r) =>
  `  ${r.widget.padEnd(26)}${r.key.padEnd(14)}median ${r.medianMs.toFixed(1).padStart(7)} ms   worst ` +
  `${r.worstMs.toFixed(1).padStart(7)} ms`;

/**
 * Every widget (or those named in `only`; two with `quick`) dragged in a fresh Chromium against the app built
 * from the sources (into BUILT_APP when set, else a temporary folder; `app`: see inBrowser). Returns { date, steps,
 * targetMs, rows }.
 */
export async function measureLatency({ only = [], quick = false, log = console.log, app } = {}) {
  const steps = quick ? QUICK.steps : STEPS;
  const chosen = only.length ? only : Object.keys(WIDGETS);
  const names = quick ? QUICK.widgets : chosen;
  const rows = [];
  await inBrowser(
    app,
    () => buildTemporaryApp('shading-lab-latency-'),
    async (browser, url) => {
      for (const name of names) {
        for (const drag of dragsOf(name)) {
          rows.push(await measure(browser, url, name, drag, steps, null, quick ? QUICK.pauses : PAUSES));
          log(`${rowText(rows.at(-1))}${rows.at(-1).progressive ? '   (progressive)' : ''}`);
        }
      }
    },
  );
  return { date: new Date().toISOString(), steps, targetMs: TARGET_MS, rows };
}

/** The table: widgets that answer a change in one frame, then the progressive ones, then the slowest named. */
export function printLatency({ rows, steps, targetMs }) {
  console.log(`\nFrom a change to its frame (${steps} steps of each widget's main control):`);
  for (const r of rows.filter((x) => !x.progressive)) console.log(rowText(r));
  const progressive = rows.filter((r) => r.progressive);
  if (progressive.length) console.log('Progressive (time to the first changed frame):');
  for (const r of progressive) console.log(rowText(r));
  const slow = rows.filter((r) => !r.progressive && r.medianMs > targetMs).map((r) => r.widget);
  console.log(
    slow.length
      ? `Over ${targetMs} ms (median, not progressive): ${slow.join(', ')}`
      : `Every non-progressive widget within ${targetMs} ms (median).`,
  );
}

/** Writes the full run to bench/results/latency.json (the part alone; `npm run bench` also keeps it in its report). */
export function saveLatency(latency) {
  const out = join(ROOT, 'bench/results/latency.json');
  mkdirSync(dirname(out), { recursive: true });
  writeFileSync(out, `${JSON.stringify(latency, null, 1)}\n`);
  return out;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const args = process.argv.slice(2);
  const only = args.flatMap((a, i) => (args[i - 1] === '--widget' ? [a] : []));
  const latency = await measureLatency({ only });
  printLatency(latency);
  if (only.length) {
    const out = join(ROOT, 'bench/results/latency-partial.json');
    writeFileSync(out, `${JSON.stringify(latency, null, 1)}\n`);
    console.log(`Wrote ${out}`);
  } else console.log(`Wrote ${saveLatency(latency)} (npm run bench -- --only latency also puts it in latest.json)`);
}
