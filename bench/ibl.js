// Image-based lighting, run time against error: the material lab's environment methods (mirror, split sum,
// three.js's PMREM, importance sampling with N samples) on a few materials and environments, each against the
// lab's converged Monte Carlo reference. Time: median GPU time of the approximation's pass at the lab's size.
import { buildApp, launchBrowser, openPage, serveStatic, settle } from '../tests/browser/harness.js';

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
  ['importance', 64, {}],
];

export async function measureIbl({ quick }) {
  const server = await serveStatic(await buildApp());
  const browser = await launchBrowser();
  const refSamples = quick ? 128 : 2048;
  // --quick (the bench's test): the reference stops at its first batch of 8 (REFERENCE_BATCH of
  // src/lab/lab-renderer.js, through sampleTarget's cap): only the rows' shape is checked
  const cap = quick ? 8 : null;
  const runs = quick ? 1 : 7;
  const rows = [];
  try {
    const cases = quick ? CASES.slice(0, 1) : [...CASES, ...ANISOTROPIC_CASES];
    for (const c of cases) {
      const page = await openPage(
        browser,
        server.url,
        `embed.html?w=material-lab&material=${c.material}&alpha=${c.alpha}` +
          `&environment=${c.environment}&refSamples=${refSamples}&punctual=0` + // the environment alone
          (c.anisotropy ? `&anisotropy=${c.anisotropy}` : ''),
        {
          width: 1100,
          height: 700,
          beforeLoad: (p) => cap && p.evaluateOnNewDocument((n) => (globalThis.__shadingLab = { maxSamples: n }), cap),
        },
      );
      await page.waitForFunction(
        () => {
          const lab = globalThis.__shadingLab?.widgets?.['material-lab'];
          const p = lab?.getProgress();
          return p && p.frame >= p.target;
        },
        { timeout: 900_000, polling: 500 },
      );
      const methods = c.anisotropy ? ANISOTROPIC_METHODS : METHODS;
      for (const [method, samples, more = {}] of quick ? METHODS.slice(1, 2) : methods) {
        const stats = await page.evaluate(
          async (method, samples, more, runs) => {
            const lab = globalThis.__shadingLab.widgets['material-lab'];
            const before = lab.getStats(); // a frame drawn since the update is a new object
            lab.update({ envMethod: method, samples, ...more });
            lab.remeasure(runs);
            for (;;) {
              await new Promise((r) => setTimeout(r, 100));
              const s = lab.getStats();
              const fresh = s !== before && s.samples >= s.target;
              if (fresh && s.method === method && s.samplesN === samples && s.timingRuns === runs) return s;
            }
          },
          method,
          samples,
          more,
          runs,
        );
        rows.push({
          ...c,
          method,
          ...(more.bentReflection === undefined ? {} : { bent: more.bentReflection }),
          samples: method === 'importance' ? samples : null,
          ms: stats.ms,
          rms: stats.rms,
          relative: stats.relative,
        });
      }
      if (page.errors.length) throw new Error(page.errors.join('\n'));
      await settle(page, 100);
      await page.close();
    }
  } finally {
    await browser.close();
    server.close();
  }
  return { setup: { resolution: 192, referenceSamples: cap ?? refSamples, timingRuns: runs }, rows };
}
