// npm run bench: for every family of terms, each variant's error against the float64 reference over a
// documented domain, its CPU cost (tinybench, ns per evaluation) and its GPU cost (a full-screen pass in
// headless Chromium). Prints a table and writes JSON (bench/results/latest.json, published to the app by
// publish-report.js; or --out FILE).
// --quick: a tiny budget, for the test suite (it reads only the report's shape), every browser part in one build and
// one Chromium (bench/browser-part.js).
// --family KEY: that family alone, errors and costs (CPU and GPU), merged into the existing JSON.
// --only families: only the term families' errors (Node, seconds), merged into the existing JSON; every cost
// column, the pages and the IBL rows stay as last measured. With --time-cpu the CPU column is timed again too
// (on a quiet machine only: timings taken beside other work are not comparable with the rest).
// --only measured: only the measured-BRDF part (bench/measured.js), merged into the existing JSON the same way.
// --only latency: only the time from a change to its frame, per widget (bench/latency.js), merged the same way
// and kept in bench/results/latency.json too.
// --only custom: only the user-written terms' times (bench/custom-terms.js: an edit to the redrawn widget, a full
// grade of each shader exercise), merged the same way.
// --only materialx: only the app's OpenPBR against MaterialX's reference shader (bench/openpbr-materialx.js), merged
// the same way; without the MaterialX venv (scripts/materialx-venv.sh) it says so and keeps the last figures.
// --only ibl: only the image-based lighting rows (bench/ibl.js: each environment method against the lab's Monte Carlo
// reference, the anisotropic case's bent reflection vector among them, and how converged that reference is), merged
// the same way.
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { Bench } from 'tinybench';
import { build } from 'vite';
import { FAMILIES, measureErrors } from './families.js';
import { measurePages } from './pages.js';
import { measureIbl, printIbl } from './ibl.js';
import { measureMeasured, printMeasured } from './measured.js';
import { measureLatency, printLatency, saveLatency } from './latency.js';
import { measureCustomTerms, printCustomTerms } from './custom-terms.js';
import { measureMaterialx, printMaterialx } from './openpbr-materialx.js';
import { REPORT, publishReport } from './publish-report.js';
import { ROOT, openPage } from '../tests/browser/harness.js';
import { inBrowser, sharedApp } from './browser-part.js';

const args = process.argv.slice(2);
const quick = args.includes('--quick');
const only = args.includes('--only') ? args[args.indexOf('--only') + 1] : null;
const timeCpu = only === null || args.includes('--time-cpu');
const PARTS = ['families', 'measured', 'latency', 'custom', 'materialx', 'ibl'];
if (only !== null && !PARTS.includes(only))
  throw new Error(`--only ${only}: the parts that run alone are ${PARTS.join(', ')}`);
const familyKey = args.includes('--family') ? args[args.indexOf('--family') + 1] : null;
if (familyKey && !FAMILIES.some((f) => f.key === familyKey))
  throw new Error(`--family ${familyKey}: families are ${FAMILIES.map((f) => f.key).join(', ')}`);
const out = args.includes('--out') ? resolve(args[args.indexOf('--out') + 1]) : REPORT;
const CPU_SAMPLE = 2048; // inputs per timed call
const cpuModel = () => cpus()[0]?.model ?? 'unknown';

async function cpuCosts(family) {
  // --quick: one warm-up and two timed calls of each variant (tinybench's least is 16 and 64, whatever the time)
  const budget = quick ? { time: 1, iterations: 2, warmupTime: 1, warmupIterations: 1 } : { time: 250, warmupTime: 50 };
  const bench = new Bench(budget);
  const sample = Array.from({ length: CPU_SAMPLE }, (_, i) => family.inputs[(i * 7919) % family.inputs.length]);
  let sink = 0;
  for (const v of family.variants.filter((w) => !w.untimed && !family.cpuUntimed)) {
    bench.add(v.key, () => {
      for (const a of sample) sink += v.js(...a);
    });
  }
  await bench.run();
  if (Number.isNaN(sink)) throw new Error('NaN in the CPU benchmark');
  // a reference run offline, or a family whose values are looked up (computed once)
  const untimed = family.variants.filter((v) => v.untimed || family.cpuUntimed).map((v) => [v.key, null]);
  return Object.fromEntries([
    ...bench.tasks.map((t) => [t.name, (t.result.latency.mean * 1e6) / CPU_SAMPLE]),
    ...untimed,
  ]);
}

/** The GPU page's figures, in `browser` when given (a quick run's, left open), else in a Chromium of its own. */
async function gpuCosts(browser) {
  const outDir = mkdtempSync(join(tmpdir(), 'shading-lab-bench-'));
  await build({
    root: ROOT,
    configFile: false,
    base: './',
    logLevel: 'warn',
    build: { outDir, emptyOutDir: true, rollupOptions: { input: { gpu: join(ROOT, 'bench/gpu-bench.html') } } },
  });
  // --quick: one frame of a small pass and a small sphere, enough for the report's shape
  const query = `${quick ? 'frames=1&size=32&sphereSize=64' : 'frames=9'}${familyKey ? `&family=${familyKey}` : ''}`;
  return inBrowser(
    { browser },
    () => outDir,
    async (chromium, url) => {
      const page = await openPage(
        chromium,
        url,
        `bench/gpu-bench.html?${query}`,
        // its load outlasted puppeteer's 30 s beside other work (the bench's test, at a load average of 45)
        { beforeLoad: (p) => p.setDefaultNavigationTimeout(300_000) },
      );
      await page.waitForFunction(() => window.__gpuBench?.done || window.__gpuBenchFailed, {
        timeout: 600_000,
        polling: 500,
      });
      const result = await page.evaluate(() => window.__gpuBench);
      if (page.errors.length) throw new Error(page.errors.join('\n'));
      result.chromium = await chromium.version();
      await page.close();
      return result;
    },
  );
}

/** A family's rows: each variant's kind, what it is measured against, that distance, and its costs. */
async function measureFamily(family, gpuMs, lastCpu) {
  family.configure?.({ quick });
  const errors = measureErrors(family);
  const cpu = timeCpu ? await cpuCosts(family) : lastCpu;
  // relative to the cheapest, or to the variant the family names (OpenPBR's layers: the talk's model)
  const cheapest = gpuMs[family.relativeTo] ?? Math.min(...Object.values(gpuMs).filter((ms) => ms !== null));
  const labelOf = (key) => family.variants.find((v) => v.key === key)?.label ?? null;
  return {
    key: family.key,
    title: family.title,
    domain: family.domain,
    errorOf: family.errorOf,
    ...(family.referenceNote ? { referenceNote: family.referenceNote() } : {}),
    ...(family.relativeTo ? { relativeTo: family.relativeTo } : {}),
    ...(family.cpuUntimed ? { cpuUntimed: true } : {}),
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
        gpuMsPerFrame: gpuMs[v.key] ?? null, // null: not run on the GPU (a Monte Carlo reference)
        gpuRelative: gpuMs[v.key] != null ? gpuMs[v.key] / cheapest : null,
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
    const missing = family.variants
      .filter((v) => !v.untimed && !(gpuMs[v.key] >= 0 && (family.cpuUntimed || cpu[v.key] >= 0)))
      .map((v) => `${family.key}/${v.key}`);
    if (missing.length) throw new Error(`no cost measured for ${missing.join(', ')}: run the whole bench`);
    families.push(await measureFamily(family, gpuMs, cpu));
  }
  const familiesMeasured = {
    date: new Date().toISOString(),
    cpu: cpuModel(),
    node: process.version,
    timedCpu: timeCpu,
  };
  return { ...last, families, familiesMeasured };
}

/** The last full report (or a bare one when there is none yet), for a part measured alone. */
const lastReport = () =>
  existsSync(out) ? JSON.parse(readFileSync(out, 'utf8')) : { version: 1, date: new Date().toISOString(), quick };

/** Every part; a quick run's browser parts share one build and one Chromium (browser-part.js). */
async function everything() {
  const app = quick ? await sharedApp() : undefined;
  try {
    return await everyPart(app);
  } finally {
    await app?.close();
  }
}

async function everyPart(app) {
  const gpu = await gpuCosts(app?.browser);
  const pages = await measurePages({ quick, app });
  const ibl = await measureIbl({ quick, app });
  const families = [];
  for (const family of FAMILIES) families.push(await measureFamily(family, gpu.results[family.key]));
  return {
    version: 1,
    date: new Date().toISOString(),
    quick,
    machine: {
      cpu: cpuModel(),
      cores: cpus().length,
      node: process.version,
      chromium: gpu.chromium,
      gpuRenderer: gpu.renderer,
    },
    gpuSetup: { ...gpu.setup, baselineMsPerFrame: gpu.baselineMs },
    families,
    versusThree: gpu.versusThree,
    pages,
    ibl,
    measured: measureMeasured({ quick }),
    latency: await measureLatency({ quick, app }),
    custom: await measureCustomTerms({ quick, app }),
    // --quick (the bench's test) leaves it out: MaterialX's shader alone takes minutes to compile in SwiftShader
    materialx: quick ? undefined : ((await measureMaterialx()) ?? lastReport().materialx),
  };
}

/** --family KEY: that family measured whole (errors, CPU, GPU), replacing its entry in the last report. */
async function oneFamily() {
  if (!existsSync(out)) throw new Error(`--family updates ${out}, which does not exist: run the whole bench`);
  const last = JSON.parse(readFileSync(out, 'utf8'));
  const family = FAMILIES.find((f) => f.key === familyKey);
  const measured = await measureFamily(family, (await gpuCosts()).results[family.key]);
  const families = FAMILIES.map((f) =>
    f.key === familyKey ? measured : last.families.find((g) => g.key === f.key),
  ).filter(Boolean);
  return { ...last, families, familyMeasured: { ...last.familyMeasured, [familyKey]: new Date().toISOString() } };
}

const report = familyKey
  ? await oneFamily()
  : only === 'families'
    ? await familiesOnly()
    : only === 'measured'
      ? { ...lastReport(), measured: measureMeasured({ quick }) }
      : only === 'latency'
        ? { ...lastReport(), latency: await measureLatency({ quick }) }
        : only === 'custom'
          ? { ...lastReport(), custom: await measureCustomTerms({ quick }) }
          : only === 'materialx'
            ? { ...lastReport(), materialx: (await measureMaterialx()) ?? lastReport().materialx }
            : only === 'ibl'
              ? { ...lastReport(), ibl: await measureIbl({ quick }) }
              : await everything();
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, `${JSON.stringify(report, null, 1)}\n`);
if (out === REPORT) publishReport();
if (report.latency && !quick && (only === null || only === 'latency')) saveLatency(report.latency);

if (only === 'measured') {
  printMeasured(report.measured);
  console.log(`\nWrote ${out} (the measured-BRDF part only; the rest is from the run of ${report.date.slice(0, 10)})`);
  process.exit(0);
}
if (only === 'custom') {
  printCustomTerms(report.custom);
  console.log(`\nWrote ${out} (the custom-term part only; the rest is from the run of ${report.date.slice(0, 10)})`);
  process.exit(0);
}
if (only === 'materialx') {
  if (report.materialx) printMaterialx(report.materialx);
  console.log(`\nWrote ${out} (the MaterialX part only; the rest is from the run of ${report.date.slice(0, 10)})`);
  process.exit(0);
}
if (only === 'ibl') {
  printIbl(report.ibl);
  const rest = `the rest is from the run of ${report.date.slice(0, 10)}`;
  console.log(`\nWrote ${out} (the image-based lighting part only; ${rest})`);
  process.exit(0);
}
if (only === 'latency') {
  printLatency(report.latency);
  console.log(`\nWrote ${out} (the latency part only; the rest is from the run of ${report.date.slice(0, 10)})`);
  process.exit(0);
}
const pad = (s, n) => String(s).padEnd(n);
const g = report.gpuSetup;
console.log(
  `Machine: ${report.machine.cpu} (${report.machine.cores} cores), Node ${report.machine.node}, ` +
    `${report.machine.chromium}, GPU: ${report.machine.gpuRenderer}`,
);
console.log(
  `GPU pass: ${g.size}² pixels × ${g.loops} evaluations, median of ${g.frames} drained frames; the empty pass ` +
    `(x·y) takes ${g.baselineMsPerFrame.toFixed(2)} ms of each.`,
);
const fixed = (x, digits) => (x === null ? '—' : x.toFixed(digits)); // null: a reference not timed
for (const f of report.families.filter((g) => !familyKey || g.key === familyKey)) {
  console.log(`\n${f.title} — ${f.errorOf} over ${f.domain}${f.referenceNote ? ` (${f.referenceNote})` : ''}`);
  console.log(
    '  ' +
      [pad('variant', 42), pad('measured against', 52), pad('max |Δ|', 11), pad('RMS', 11)].join('') +
      [pad('CPU ns/eval', 13), pad('GPU ms/frame', 14), 'GPU relative'].join(''),
  );
  for (const v of f.variants) {
    const d = v.error ?? v.difference;
    const what =
      v.kind === 'reference'
        ? 'reference'
        : `${v.kind === 'difference' ? 'differs from' : 'error vs'} ${v.againstLabel}`;
    console.log(
      '  ' +
        [pad(v.label, 42), pad(what, 52), pad(d.maxAbs.toExponential(2), 11), pad(d.rms.toExponential(2), 11)].join(
          '',
        ) +
        [pad(fixed(v.cpuNsPerEval, 2), 13), pad(fixed(v.gpuMsPerFrame, 2), 14), fixed(v.gpuRelative, 2)].join('') +
        (v.gpuRelative === null ? '' : '×'),
    );
  }
}
if (familyKey) {
  console.log(`\nWrote ${out} (${familyKey} replaced; everything else as it was)`);
  process.exit(0);
}
if (only === 'families') {
  const kept = timeCpu ? 'the GPU columns' : 'the CPU and GPU columns';
  console.log(`\nWrote ${out} (families only; ${kept} are from the run of ${report.date.slice(0, 10)})`);
  process.exit(0);
}
const { versusThree: vt, ibl, pages } = report;
console.log(`\nSphere at ${vt.size}² with GGX + height-correlated Smith + Schlick + Lambert + one punctual light:`);
console.log(
  `  ours ${vt.oursMsPerFrame.toFixed(2)} ms/frame, three.js MeshStandardMaterial ` +
    `${vt.threeMsPerFrame.toFixed(2)} ms/frame: ratio ${vt.ratio.toFixed(2)}`,
);
printIbl(ibl);
console.log(
  `\n  ${pad('page', 30)}${pad('JS (KiB, uncompressed)', 30)}${pad('files', 7)}${pad('load (ms)', 11)}first frame (ms)`,
);
for (const p of pages)
  console.log(
    '  ' +
      [pad(p.page, 30), pad(p.jsKB.toFixed(0), 30), pad(p.jsFiles, 7), pad(p.loadMs.toFixed(0), 11)].join('') +
      (p.firstFrameMs === null ? '—' : p.firstFrameMs.toFixed(0)),
  );
printMeasured(report.measured);
printLatency(report.latency);
printCustomTerms(report.custom);
console.log(`\nWrote ${out}`);
