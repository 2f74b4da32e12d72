// Load only what is opened, measured: each page's JavaScript (what the browser actually fetched) and the
// time to its first frame (the render loop's first draw) or, for pages without a 3-D view, to load.
import { buildApp, openPage, settle } from '../tests/browser/harness.js';
import { inBrowser } from './browser-part.js';

export const MEASURED_PAGES = [
  'index.html',
  'media.html',
  'surfaces.html',
  'brdf.html',
  'microfacets.html',
  'fresnel.html',
  'ndf.html',
  'visibility.html',
  'diffuse.html',
  'rendering.html',
  'performance.html',
  'exercises.html',
  'embed.html?w=fresnel-zones',
  'parity.html',
];

/** Timestamps the first frame the app's render loop draws (it counts frames in __shadingLab.frames). */
function recordFirstFrame() {
  let frames = 0;
  const lab = { firstFrameAt: null };
  Object.defineProperty(lab, 'frames', {
    get: () => frames,
    set(v) {
      if (lab.firstFrameAt === null && v > 0) lab.firstFrameAt = performance.now();
      frames = v;
    },
  });
  window.__shadingLab = lab;
}

/** The pages measured; `quick` (the bench's test): two, to check the part runs; `app`: see inBrowser. */
export function measurePages({ quick = false, app } = {}) {
  return inBrowser(
    app,
    () => buildApp(),
    async (browser, url) => {
      const rows = [];
      for (const path of quick ? ['index.html', 'fresnel.html'] : MEASURED_PAGES) {
        const page = await openPage(browser, url, path, {
          beforeLoad: (p) => p.evaluateOnNewDocument(recordFirstFrame),
        });
        await settle(page, quick ? 500 : 2500); // quick: the figures are not read, only their shape
        rows.push(
          await page.evaluate((p) => {
            const js = performance.getEntriesByType('resource').filter((r) => r.name.endsWith('.js'));
            const nav = performance.getEntriesByType('navigation')[0];
            return {
              page: p,
              jsKB: js.reduce((s, r) => s + r.encodedBodySize, 0) / 1024,
              jsFiles: js.length,
              loadMs: nav.loadEventEnd,
              firstFrameMs: globalThis.__shadingLab.firstFrameAt,
            };
          }, path),
        );
        await page.close();
      }
      return rows;
    },
  );
}
