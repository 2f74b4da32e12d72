// npm run bench:latency [-- --widget NAME …]: for every widget, the time from a state change to the changed frame,
// over a scripted drag (a slider swept in small steps, one change after the previous frame is done): median and
// worst. "Done" is: the render loop's next animation frame has run (it draws what changed), every canvas of the
// widget has finished its GPU work (a one-pixel read-back), and the browser reached the following frame. A widget
// that keeps drawing a second after the drag (a Monte Carlo reference converging) is progressive and is reported
// apart: its number is the time to its first changed frame. Writes bench/results/latency.json.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { WIDGETS } from '../src/widgets/registry.js';
import { ROOT, buildApp, launchBrowser, openPage, serveStatic, settle } from '../tests/browser/harness.js';

const args = process.argv.slice(2);
const only = args.flatMap((a, i) => (args[i - 1] === '--widget' ? [a] : []));
const STEPS = 24;
const TARGET_MS = 50;
// Light state for software rendering: fewer path-traced samples (as the browser tests do).
const QUICK = { media: '&samples=16', 'material-lab': '&refSamples=128', 'lighting-models': '&refSamples=128' };

/**
 * The control a user would drag, per widget: [key, from, to] (a number swept in STEPS steps) or [key, [values]].
 * A new widget adds its row (the bench stops on a widget without one).
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
  'brdf-lobe': ['lightTheta', 10, 70],
  'ndf-explorer': ['hwhm', 5, 25],
  'visibility-explorer': ['alpha', 0.1, 0.8],
  microfacets: ['alpha', 0.2, 0.8],
  energy: ['samples', [32, 64, 96, 128, 160, 192, 224, 256]],
  'diffuse-explorer': ['lightTheta', 10, 70],
  'material-lab': ['lightTheta', 10, 70],
  'lighting-models': ['alpha', 0.2, 0.6],
};

function dragValues(name) {
  const drag = DRAGS[name];
  if (!drag) throw new Error(`bench/latency.js: add the drag of ${name} to DRAGS`);
  const [key, from, to] = drag;
  const values = Array.isArray(from)
    ? [...from, ...from].slice(0, STEPS)
    : Array.from({ length: STEPS }, (_, i) => from + ((to - from) * i) / (STEPS - 1));
  return { key, values };
}

/**
 * In the page: one change, timed to its finished frame (ms). With `viaLoop`, the frame is the render loop's next
 * draw (it may come frames later, after work off the main thread); otherwise the next animation frame.
 */
function timeChange(name, key, value, viaLoop) {
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

async function measure(browser, url, name) {
  const { key, values } = dragValues(name);
  const page = await openPage(browser, url, `embed.html?w=${name}${QUICK[name] ?? ''}`, { width: 1280, height: 2600 });
  await page.waitForFunction((n) => globalThis.__shadingLab?.widgets?.[n], { timeout: 60_000 }, name);
  await settle(page, 1500);
  // does a change go through the render loop (a 3-D view)? then each change waits for its draw
  const before = await page.evaluate(() => globalThis.__shadingLab.frames);
  await page.evaluate((n, k, v) => globalThis.__shadingLab.widgets[n].update({ [k]: v }), name, key, values.at(-1));
  await settle(page, 1500);
  const viaLoop = (await page.evaluate(() => globalThis.__shadingLab.frames)) > before;
  let ms = [];
  for (const v of values) ms.push(await page.evaluate(timeChange, name, key, v, viaLoop));
  ms = ms.filter((x) => x !== null);
  const after = await page.evaluate(() => globalThis.__shadingLab.frames);
  await settle(page, 1000);
  const progressive = (await page.evaluate(() => globalThis.__shadingLab.frames)) - after > 2;
  await page.close();
  return { widget: name, key, steps: ms.length, medianMs: quantile(ms, 0.5), worstMs: Math.max(...ms), progressive };
}

const server = await serveStatic(await buildApp());
const browser = await launchBrowser();
const rows = [];
try {
  for (const name of Object.keys(WIDGETS).filter((n) => !only.length || only.includes(n))) {
    rows.push(await measure(browser, server.url, name));
    const r = rows.at(-1);
    console.log(
      `${r.widget.padEnd(22)}${r.key.padEnd(14)}median ${r.medianMs.toFixed(1).padStart(7)} ms   worst ` +
        `${r.worstMs.toFixed(1).padStart(7)} ms${r.progressive ? '   (progressive)' : ''}`,
    );
  }
} finally {
  await browser.close();
  server.close();
}
const slow = rows.filter((r) => !r.progressive && r.medianMs > TARGET_MS).map((r) => r.widget);
console.log(
  slow.length
    ? `Over ${TARGET_MS} ms (median, not progressive): ${slow.join(', ')}`
    : `Every non-progressive widget within ${TARGET_MS} ms (median).`,
);
const out = join(ROOT, 'bench/results', only.length ? 'latency-partial.json' : 'latency.json');
mkdirSync(join(ROOT, 'bench/results'), { recursive: true });
writeFileSync(
  out,
  `${JSON.stringify({ date: new Date().toISOString(), steps: STEPS, targetMs: TARGET_MS, rows }, null, 1)}\n`,
);
console.log(`Wrote ${out}`);
