// npm run bench: for every family of terms, each variant's error against the float64 reference over a
// documented domain, its CPU cost (tinybench, ns per evaluation) and its GPU cost (a full-screen pass in
// headless Chromium). Prints a table and writes JSON (bench/results/latest.json, or --out FILE).
// --quick: a tiny budget, for the test suite. --family KEY: one family alone, merged into the existing results.
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { Bench } from 'tinybench';
import { build } from 'vite';
import { FAMILIES, measureErrors } from './families.js';
import { measurePages } from './pages.js';
import { measureIbl } from './ibl.js';
import { ROOT, launchBrowser, openPage, serveStatic } from '../tests/browser/harness.js';

const args = process.argv.slice(2);
const quick = args.includes('--quick');
// --family KEY: measure that family alone and replace its entry in the existing results (the rest is kept)
const only = args.includes('--family') ? args[args.indexOf('--family') + 1] : null;
const chosen = FAMILIES.filter((f) => !only || f.key === only);
if (!chosen.length) throw new Error(`no bench family '${only}' (families: ${FAMILIES.map((f) => f.key).join(', ')})`);
const out = args.includes('--out') ? resolve(args[args.indexOf('--out') + 1]) : join(ROOT, 'bench/results/latest.json');
const CPU_SAMPLE = 2048; // inputs per timed call

async function cpuCosts(family) {
  const bench = new Bench({ time: quick ? 5 : 250, warmupTime: quick ? 2 : 50 });
  const sample = Array.from({ length: CPU_SAMPLE }, (_, i) => family.inputs[(i * 7919) % family.inputs.length]);
  let sink = 0;
  for (const v of family.variants) {
    bench.add(v.key, () => {
      for (const a of sample) sink += v.js(...a);
    });
  }
  await bench.run();
  if (Number.isNaN(sink)) throw new Error('NaN in the CPU benchmark');
  return Object.fromEntries(bench.tasks.map((t) => [t.name, (t.result.latency.mean * 1e6) / CPU_SAMPLE]));
}

async function gpuCosts() {
  const outDir = mkdtempSync(join(tmpdir(), 'shading-lab-bench-'));
  await build({ root: ROOT, configFile: false, base: './', logLevel: 'warn', build: { outDir, emptyOutDir: true, rollupOptions: { input: { gpu: join(ROOT, 'bench/gpu-bench.html') } } } });
  const server = await serveStatic(outDir);
  const browser = await launchBrowser();
  try {
    const page = await openPage(browser, server.url, `bench/gpu-bench.html?frames=${quick ? 1 : 9}${only ? `&family=${only}` : ''}`);
    await page.waitForFunction(() => window.__gpuBench?.done, { timeout: 600_000, polling: 500 });
    const result = await page.evaluate(() => window.__gpuBench);
    if (page.errors.length) throw new Error(page.errors.join('\n'));
    result.chromium = await browser.version();
    return result;
  } finally {
    await browser.close();
    server.close();
  }
}

const gpu = await gpuCosts();
const families = [];
for (const family of chosen) {
  family.configure?.({ quick });
  const errors = measureErrors(family);
  const cpu = await cpuCosts(family);
  const gpuMs = gpu.results[family.key];
  const cheapest = Math.min(...Object.values(gpuMs));
  families.push({
    key: family.key,
    title: family.title,
    domain: family.domain,
    errorOf: family.errorOf,
    ...(family.kind ? { kind: family.kind } : {}),
    ...(family.referenceLabel ? { referenceLabel: family.referenceLabel } : {}),
    ...(family.referenceNote ? { referenceNote: family.referenceNote() } : {}),
    variants: family.variants.map((v, i) => ({
      key: v.key,
      label: v.label,
      error: { maxAbs: errors[i].maxAbs, rms: errors[i].rms, maxAt: errors[i].maxAt },
      cpuNsPerEval: cpu[v.key],
      gpuMsPerFrame: gpuMs[v.key],
      gpuRelative: gpuMs[v.key] / cheapest,
    })),
  });
}

/** --family: the existing results with this family's entry replaced (appended if new). */
function mergedInto(path) {
  const old = JSON.parse(readFileSync(path, 'utf8'));
  const at = old.families.findIndex((f) => f.key === only);
  if (at < 0) old.families.push(families[0]);
  else old.families[at] = families[0];
  return { ...old, familiesMeasured: { ...old.familiesMeasured, [only]: new Date().toISOString() } };
}

const machine = { cpu: cpus()[0]?.model ?? 'unknown', cores: cpus().length, node: process.version, chromium: gpu.chromium, gpuRenderer: gpu.renderer };
const report = only ? mergedInto(out) : {
  version: 1,
  date: new Date().toISOString(),
  quick,
  machine,
  gpuSetup: { ...gpu.setup, baselineMsPerFrame: gpu.baselineMs },
  families,
  versusThree: gpu.versusThree,
  pages: await measurePages(),
  ibl: await measureIbl({ quick }),
};
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, `${JSON.stringify(report, null, 1)}\n`);

const pad = (s, n) => String(s).padEnd(n);
console.log(`Machine: ${machine.cpu} (${machine.cores} cores), Node ${machine.node}, ${machine.chromium}, GPU: ${machine.gpuRenderer}`);
console.log(`GPU pass: ${gpu.setup.size}² pixels × ${gpu.setup.loops} evaluations, median of ${gpu.setup.frames} drained frames; the empty pass (x·y) takes ${gpu.baselineMs.toFixed(2)} ms of each.`);
for (const f of families) {
  console.log(`\n${f.title} — error of ${f.errorOf} over ${f.domain}${f.referenceNote ? ` (${f.referenceNote})` : ''}`);
  console.log(`  ${pad('variant', 42)}${pad('max |error|', 13)}${pad('RMS', 11)}${pad('CPU ns/eval', 13)}${pad('GPU ms/frame', 14)}GPU relative`);
  for (const v of f.variants) {
    console.log(`  ${pad(v.label, 42)}${pad(v.error.maxAbs.toExponential(2), 13)}${pad(v.error.rms.toExponential(2), 11)}${pad(v.cpuNsPerEval.toFixed(2), 13)}${pad(v.gpuMsPerFrame.toFixed(2), 14)}${v.gpuRelative.toFixed(2)}×`);
  }
}
if (only) {
  console.log(`\nWrote ${out} (${only} replaced; everything else as it was)`);
  process.exit(0);
}
const { pages, ibl } = report;
const vt = gpu.versusThree;
console.log(`\nSphere at ${vt.size}² with GGX + height-correlated Smith + Schlick + Lambert + one punctual light:`);
console.log(`  ours ${vt.oursMsPerFrame.toFixed(2)} ms/frame, three.js MeshStandardMaterial ${vt.threeMsPerFrame.toFixed(2)} ms/frame: ratio ${vt.ratio.toFixed(2)}`);
console.log(`\nImage-based lighting against the Monte Carlo reference (${ibl.setup.referenceSamples} samples/pixel), ${ibl.setup.resolution}² pixels, median of ${ibl.setup.timingRuns} runs:`);
console.log(`  ${pad('environment, material', 30)}${pad('method', 22)}${pad('GPU ms', 10)}${pad('RMS', 11)}relative`);
for (const r of ibl.rows) {
  const method = r.samples ? `importance, N = ${r.samples}` : r.method;
  console.log(`  ${pad(`${r.environment}, ${r.material} α ${r.alpha}`, 30)}${pad(method, 22)}${pad(r.ms.toFixed(2), 10)}${pad(r.rms.toExponential(2), 11)}${(r.relative * 100).toFixed(2)} %`);
}
console.log(`\n  ${pad('page', 30)}${pad('JS (KiB, uncompressed)', 30)}${pad('files', 7)}${pad('load (ms)', 11)}first frame (ms)`);
for (const p of pages) console.log(`  ${pad(p.page, 30)}${pad(p.jsKB.toFixed(0), 30)}${pad(p.jsFiles, 7)}${pad(p.loadMs.toFixed(0), 11)}${p.firstFrameMs === null ? '—' : p.firstFrameMs.toFixed(0)}`);
console.log(`\nWrote ${out}`);
