// npm run bench: for every family of terms, each variant's error against the float64 reference over a
// documented domain, its CPU cost (tinybench, ns per evaluation) and its GPU cost (a full-screen pass in
// headless Chromium). Prints a table and writes JSON (bench/results/latest.json, or --out FILE).
// --quick: a tiny budget, for the test suite.
// --only families: only the term families' errors (Node, seconds), merged into the existing JSON; every cost
// column, the pages and the IBL rows stay as last measured. With --time-cpu the CPU column is timed again too
// (on a quiet machine only: timings taken beside other work are not comparable with the rest).
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
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
const only = args.includes('--only') ? args[args.indexOf('--only') + 1] : null;
const timeCpu = only === null || args.includes('--time-cpu');
if (only !== null && only !== 'families') throw new Error(`--only ${only}: the only part that runs alone is "families"`);
const out = args.includes('--out') ? resolve(args[args.indexOf('--out') + 1]) : join(ROOT, 'bench/results/latest.json');
const CPU_SAMPLE = 2048; // inputs per timed call
const cpuModel = () => cpus()[0]?.model ?? 'unknown';

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
    const page = await openPage(browser, server.url, `bench/gpu-bench.html?frames=${quick ? 1 : 9}`);
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

/** A family's rows: each variant's kind, what it is measured against, that distance, and its costs. */
async function measureFamily(family, gpuMs, lastCpu) {
  const errors = measureErrors(family);
  const cpu = timeCpu ? await cpuCosts(family) : lastCpu;
  const cheapest = Math.min(...Object.values(gpuMs));
  const labelOf = (key) => family.variants.find((v) => v.key === key)?.label ?? null;
  return {
    key: family.key,
    title: family.title,
    domain: family.domain,
    errorOf: family.errorOf,
    variants: family.variants.map((v, i) => {
      const { maxAbs, rms, maxAt } = errors[i];
      return {
        key: v.key,
        label: v.label,
        kind: v.kind,
        against: v.against ?? null,
        againstLabel: labelOf(v.against),
        [v.kind === 'difference' ? 'difference' : 'error']: { maxAbs, rms, maxAt },
        cpuNsPerEval: cpu[v.key],
        gpuMsPerFrame: gpuMs[v.key],
        gpuRelative: gpuMs[v.key] / cheapest,
      };
    }),
  };
}

/** Only the families' errors (and, asked, CPU times), measured now, into the last full report. */
async function familiesOnly() {
  if (!existsSync(out)) throw new Error(`--only families updates ${out}, which does not exist: run the whole bench`);
  const last = JSON.parse(readFileSync(out, 'utf8'));
  const lastOf = (key, field) => {
    const variants = last.families.find((f) => f.key === key)?.variants ?? [];
    return Object.fromEntries(variants.map((v) => [v.key, v[field]]));
  };
  const families = [];
  for (const family of FAMILIES) {
    const [gpuMs, cpu] = [lastOf(family.key, 'gpuMsPerFrame'), lastOf(family.key, 'cpuNsPerEval')];
    const missing = family.variants.filter((v) => !(gpuMs[v.key] >= 0 && cpu[v.key] >= 0)).map((v) => `${family.key}/${v.key}`);
    if (missing.length) throw new Error(`no cost measured for ${missing.join(', ')}: run the whole bench`);
    families.push(await measureFamily(family, gpuMs, cpu));
  }
  const familiesMeasured = { date: new Date().toISOString(), cpu: cpuModel(), node: process.version, timedCpu: timeCpu };
  return { ...last, families, familiesMeasured };
}

async function everything() {
  const gpu = await gpuCosts();
  const pages = await measurePages();
  const ibl = await measureIbl({ quick });
  const families = [];
  for (const family of FAMILIES) families.push(await measureFamily(family, gpu.results[family.key]));
  return {
    version: 1,
    date: new Date().toISOString(),
    quick,
    machine: { cpu: cpuModel(), cores: cpus().length, node: process.version, chromium: gpu.chromium, gpuRenderer: gpu.renderer },
    gpuSetup: { ...gpu.setup, baselineMsPerFrame: gpu.baselineMs },
    families,
    versusThree: gpu.versusThree,
    pages,
    ibl,
  };
}

const report = only === 'families' ? await familiesOnly() : await everything();
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, `${JSON.stringify(report, null, 1)}\n`);

const pad = (s, n) => String(s).padEnd(n);
const g = report.gpuSetup;
console.log(`Machine: ${report.machine.cpu} (${report.machine.cores} cores), Node ${report.machine.node}, ${report.machine.chromium}, GPU: ${report.machine.gpuRenderer}`);
console.log(`GPU pass: ${g.size}² pixels × ${g.loops} evaluations, median of ${g.frames} drained frames; the empty pass (x·y) takes ${g.baselineMsPerFrame.toFixed(2)} ms of each.`);
for (const f of report.families) {
  console.log(`\n${f.title} — ${f.errorOf} over ${f.domain}`);
  console.log(`  ${pad('variant', 42)}${pad('measured against', 52)}${pad('max |Δ|', 11)}${pad('RMS', 11)}${pad('CPU ns/eval', 13)}${pad('GPU ms/frame', 14)}GPU relative`);
  for (const v of f.variants) {
    const d = v.error ?? v.difference;
    const what = v.kind === 'reference' ? 'reference' : `${v.kind === 'difference' ? 'differs from' : 'error vs'} ${v.againstLabel}`;
    console.log(`  ${pad(v.label, 42)}${pad(what, 52)}${pad(d.maxAbs.toExponential(2), 11)}${pad(d.rms.toExponential(2), 11)}${pad(v.cpuNsPerEval.toFixed(2), 13)}${pad(v.gpuMsPerFrame.toFixed(2), 14)}${v.gpuRelative.toFixed(2)}×`);
  }
}
if (only === 'families') {
  const kept = timeCpu ? 'the GPU columns' : 'the CPU and GPU columns';
  console.log(`\nWrote ${out} (families only; ${kept} are from the run of ${report.date.slice(0, 10)})`);
  process.exit(0);
}
const { versusThree: vt, ibl, pages } = report;
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
