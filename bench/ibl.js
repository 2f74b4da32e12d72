// Image-based lighting, run time against error: the material lab's environment methods (mirror, split sum,
// three.js's PMREM, importance sampling with N samples) on a few materials and environments, each against the
// lab's converged Monte Carlo reference. Time: median GPU time of the approximation's pass at the lab's size.
// Error: relative RMS over the sphere, √(Σ|approximation − reference|² / Σ|reference|²) over its pixels and channels
// (src/lab/lab-renderer.js). How converged the reference is, is measured too: every method again against a
// reference of a quarter of the samples (REFERENCE_CHECK); the approximations are deterministic (importance sampling
// takes the same Hammersley pattern on every pixel), so the squared error grows by three times the full reference's
// own noise, σ²(N/4) − σ²(N) = 3σ²(N), and √((e²(N/4) − e²(N)) / 3) is that noise (relative, like the errors).
import { loadavg } from 'node:os';
import { buildApp, openPage, settle } from '../tests/browser/harness.js';
import { inBrowser } from './browser-part.js';
import { iblCaseWords as caseWords, iblMethodWords as methodWords } from '../src/pages/ibl-note.js';

const CASES = [
  { environment: 'studio', material: 'gold', alpha: 0.1 },
  { environment: 'studio', material: 'manual', alpha: 0.35 },
  { environment: 'sky', material: 'iron', alpha: 0.5 },
  { environment: 'sky', material: 'manual', alpha: 0.1 },
];
const METHODS = [['mirror', 1], ['split-sum', 1], ['pmrem', 1], ...[4, 16, 64, 256].map((n) => ['importance', n])];
// brushed metal (issue 28): the split sum's prefilter has no anisotropic form, so it reads the light along the bent
// reflection vector (Filament, three.js) or the mirror direction; importance sampling has the anisotropic lobe
const ANISOTROPIC_CASES = [{ environment: 'studio', material: 'aluminum', alpha: 0.2, anisotropy: 0.8 }];
const ANISOTROPIC_METHODS = [
  ['split-sum', 1, { bentReflection: true }],
  ['split-sum', 1, { bentReflection: false }],
  ...[16, 64, 256].map((n) => ['importance', n, {}]),
];
export const ERROR_OF =
  'relative RMS error of the radiance over the sphere: √(Σ|approximation − reference|² / Σ|reference|²)';
const REFERENCE_CHECK = 4; // the check's reference has 1/4 of the samples

/**
 * `fn(...args)` in the page until it returns something truthy, within `budgetMs`. Each call is short; one that the
 * page's main thread holds past the protocol's timeout (a software-WebGL frame of the reference on a loaded machine
 * outlasted its 180 s) is made again, which is harmless: every call here may run twice.
 */
async function untilPage(page, fn, args, budgetMs = 1_800_000) {
  const t0 = Date.now();
  for (;;) {
    try {
      const value = await page.evaluate(fn, ...args);
      if (value) return value;
    } catch (error) {
      if (!/timed out/.test(String(error?.message))) throw error;
    }
    if (Date.now() - t0 > budgetMs) throw new Error(`the IBL bench waited ${budgetMs / 1000} s for its page`);
    await new Promise((r) => setTimeout(r, 500));
  }
}

/** The lab at `c` with a reference of `refSamples` (capped at `cap`), once the reference has its samples. */
async function openCase(browser, url, c, refSamples, cap) {
  const page = await openPage(
    browser,
    url,
    `embed.html?w=material-lab&material=${c.material}&alpha=${c.alpha}` +
      `&environment=${c.environment}&refSamples=${refSamples}&punctual=0` + // the environment alone
      (c.anisotropy ? `&anisotropy=${c.anisotropy}` : ''),
    {
      width: 1100,
      height: 700,
      beforeLoad: async (p) => {
        p.setDefaultNavigationTimeout(300_000); // a load beside other work outlasts puppeteer's 30 s
        if (cap) await p.evaluateOnNewDocument((n) => (globalThis.__shadingLab = { maxSamples: n }), cap);
      },
    },
  );
  const converged = () => {
    const p = globalThis.__shadingLab?.widgets?.['material-lab']?.getProgress();
    return Boolean(p && p.frame >= p.target);
  };
  await untilPage(page, converged, []);
  return page;
}

/** The lab's stats for one method, its pass timed `runs` times, once its error is against the whole reference. */
async function measureMethod(page, [method, samples, more = {}], runs) {
  const ask = (method, samples, more, runs) => {
    const lab = globalThis.__shadingLab.widgets['material-lab'];
    globalThis.__iblBefore = lab.getStats(); // a frame drawn since the update is a new object
    lab.update({ envMethod: method, samples, ...more });
    lab.remeasure(runs);
    return true;
  };
  const answer = (method, samples, runs) => {
    const s = globalThis.__shadingLab.widgets['material-lab'].getStats();
    const fresh = s !== globalThis.__iblBefore && s.samples >= s.target;
    return fresh && s.method === method && s.samplesN === samples && s.timingRuns === runs ? s : null;
  };
  await untilPage(page, ask, [method, samples, more, runs]);
  return untilPage(page, answer, [method, samples, runs]);
}

/** Each of `methods` on case `c` against a reference of `refSamples`: its stats, in order. */
async function measureCase(browser, url, c, methods, { refSamples, cap, runs }) {
  const page = await openCase(browser, url, c, refSamples, cap);
  const stats = [];
  for (const m of methods) stats.push(await measureMethod(page, m, runs));
  if (page.errors.length) throw new Error(page.errors.join('\n'));
  await settle(page, 100);
  await page.close();
  return stats;
}

/** The full reference's own relative noise from each method's error against it (e) and against the check's (q). */
export function referenceNoise(full, check) {
  const each = full.map((e, i) => Math.sqrt(Math.max(0, check[i] ** 2 - e ** 2) / (REFERENCE_CHECK - 1)));
  return { each, mean: each.reduce((a, b) => a + b, 0) / each.length };
}

/** The rows of every case (one with `quick`, the bench's test); `app`: see inBrowser. */
export async function measureIbl({ quick, app }) {
  const refSamples = quick ? 128 : 2048;
  // --quick (the bench's test): the reference stops at its first batch of 8 (REFERENCE_BATCH of
  // src/lab/lab-renderer.js, through sampleTarget's cap): only the rows' shape is checked; no reference check
  const cap = quick ? 8 : null;
  const runs = quick ? 1 : 7;
  const rows = [];
  const checks = [];
  const loadBefore = loadavg()[0]; // its GPU times depend on what else runs: said beside them
  await inBrowser(
    app,
    () => buildApp(),
    async (browser, url) => {
      for (const c of quick ? CASES.slice(0, 1) : [...CASES, ...ANISOTROPIC_CASES]) {
        const methods = quick ? METHODS.slice(1, 2) : c.anisotropy ? ANISOTROPIC_METHODS : METHODS;
        const stats = await measureCase(browser, url, c, methods, { refSamples, cap, runs });
        methods.forEach(([method, samples, more = {}], i) =>
          rows.push({
            ...c,
            method,
            ...(more.bentReflection === undefined ? {} : { bent: more.bentReflection }),
            samples: method === 'importance' ? samples : null,
            ms: stats[i].ms,
            rms: stats[i].rms,
            relative: stats[i].relative,
          }),
        );
        if (quick) continue;
        const fewer = refSamples / REFERENCE_CHECK;
        const check = await measureCase(browser, url, c, methods, { refSamples: fewer, cap, runs: 1 });
        const { each, mean } = referenceNoise(
          stats.map((s) => s.relative),
          check.map((s) => s.relative),
        );
        checks.push({ ...c, checkSamples: fewer, relativeAtCheck: check.map((s) => s.relative), each, noise: mean });
      }
    },
  );
  return {
    date: new Date().toISOString(),
    setup: { resolution: 192, referenceSamples: cap ?? refSamples, timingRuns: runs },
    loadAverage: { before: loadBefore, after: loadavg()[0] },
    errorOf: ERROR_OF,
    rows,
    referenceChecks: checks,
  };
}

const pad = (s, n) => String(s).padEnd(n);
export function printIbl(ibl) {
  console.log(
    `\nImage-based lighting against the Monte Carlo reference (${ibl.setup.referenceSamples} samples/pixel), ` +
      `${ibl.setup.resolution}² pixels, median of ${ibl.setup.timingRuns} runs; ${ibl.errorOf ?? 'relative RMS'}:`,
  );
  console.log(`  ${pad('environment, material', 44)}${pad('method', 32)}${pad('GPU ms', 10)}${pad('RMS', 11)}relative`);
  for (const r of ibl.rows) {
    console.log(
      '  ' +
        [pad(caseWords(r), 44), pad(methodWords(r), 32), pad(r.ms.toFixed(2), 10)].join('') +
        `${pad(r.rms.toExponential(2), 11)}${(r.relative * 100).toFixed(2)} %`,
    );
  }
  for (const c of ibl.referenceChecks ?? [])
    console.log(
      `  reference's own noise, ${caseWords(c)}: ${(c.noise * 100).toFixed(2)} % (from a ${c.checkSamples}-sample ` +
        `check; per method ${c.each.map((x) => (x * 100).toFixed(2)).join(', ')} %)`,
    );
}
