// Pages opened under the app's Content-Security-Policy with every violation recorded: the built pages, and what
// each page does on load to wait for. Used by csp.test.js and axe.test.js.
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import { WAIT_MS, baseUrl, countDrawCalls } from './helpers.js';
import { untilCalm } from './idle.js';
import { ROOT, openPage } from './harness.js';

/** Every violation in the page and its same-origin frames, in window.top.__csp (installed before any script). */
export function recordViolations() {
  document.addEventListener('securitypolicyviolation', (e) => {
    (window.top.__csp ??= []).push(
      `${e.violatedDirective}: ${e.blockedURI || e.sample || '(inline)'} in ${location.pathname}`,
    );
  });
}

export const BUILT = readdirSync(join(ROOT, 'dist'))
  .filter((f) => f.endsWith('.html'))
  .sort();
// when each page has finished what it does on load (its widgets mounted, its data drawn); run in the page
const READY = {
  'exercises.html': () => globalThis.__shadingLab?.exercise?.ready,
  'tour.html': () => globalThis.__shadingLab?.tour?.ready,
  'parity.html': () => globalThis.__shadingLab?.parity,
  'performance.html': () => globalThis.__shadingLab?.performance,
  'wall.html': () => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length > 0,
  'author.html': () => document.querySelector('.author-library-list li'), // the built-in exercises listed
};
const oneWidget = () => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length === 1;
const chapterReady = () =>
  document.querySelectorAll('[data-slot]').length === Object.keys(globalThis.__shadingLab?.widgets ?? {}).length;
const ONE_EXERCISE = [
  {
    id: 'csp-check',
    chapter: 'media',
    title: 'A set from a data: URL',
    prompt: 'Fetched under connect-src.',
    widget: 'media',
    state: { medium: 'water', view: 'one' },
    locked: ['medium', 'view'],
    grader: 'transmittance-depth',
    params: { channel: 'r' },
    tolerance: 1,
  },
];

// the lab's references with fewer samples, as every browser test has them on software WebGL; the parity page with
// four of its 105 rows (seconds of shaders on load: every row is parity.test.js's), a first row of its function and
// a second (no anchor), a row of the page's tolerance and one of its own
const LIGHT = {
  'rendering.html': 'rendering.html?lab.refSamples=128&models.refSamples=128',
  'parity.html': 'parity.html?only=fresnelSchlick,diffuseOrenNayar',
};

/** The pages to run: every built HTML file, the embed with a widget, exercises with ?src=. */
export const POLICY_PAGES = [
  ...BUILT.filter((f) => f !== 'embed.html').map((f) => LIGHT[f] ?? f),
  'embed.html?w=fresnel-zones',
  `exercises.html?src=${encodeURIComponent(`data:application/json,${JSON.stringify(ONE_EXERCISE)}`)}`,
];

/**
 * Opens `path` with its violations recorded (window.__csp), its draw calls counted (window.__drawCalls) and its
 * progressive views capped at `maxSamples` if given, and waits until it has done what it does on load (an embed
 * with a widget: that widget mounted) and has nothing pending (untilCalm in idle.js).
 */
export async function openUnderPolicy(browser, path, { width = 1100, height = 800, maxSamples } = {}) {
  const page = await openPage(browser, baseUrl(), path, {
    width,
    height,
    beforeLoad: async (p) => {
      await p.evaluateOnNewDocument(recordViolations);
      await p.evaluateOnNewDocument(countDrawCalls);
      // a cap on progressive views' samples (debug-hooks.js sampleTarget), seeded before the app makes its hooks
      if (maxSamples) await p.evaluateOnNewDocument((n) => (globalThis.__shadingLab = { maxSamples: n }), maxSamples);
    },
  });
  const ready = path.startsWith('embed.html?w=') ? oneWidget : (READY[path.split('?')[0]] ?? chapterReady);
  if (ready) await page.waitForFunction(ready, { timeout: WAIT_MS });
  await untilCalm(page); // what the load set going (its frames and timed pauses) done
  return page;
}
