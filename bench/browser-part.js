// The Chromium and the served app a browser part of the bench runs in. A full run (or a part run alone) gives each
// part a Chromium of its own and its own build, as its figures have always been measured; a quick run (the bench's
// test, which reads only the report's shape) builds and serves the app once and shares one Chromium between its
// parts: a launch and a close cost 3 to 5 s each at a load average of 14.
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { buildApp, launchBrowser, serveStatic } from '../tests/browser/harness.js';

/** The app built into BUILT_APP when set (a build made by the same test run), else into a temporary folder. */
export const buildTemporaryApp = (prefix) =>
  buildApp(resolve(process.env.BUILT_APP ?? mkdtempSync(join(tmpdir(), prefix))));

/**
 * `part(browser, url)` in `app.browser` against the app served at `app.url` when given (both left open), else in a
 * Chromium launched here against `build()`'s folder served here, both closed after.
 */
export async function inBrowser(app, build, part) {
  const server = app?.url ? null : await serveStatic(await build());
  const browser = app?.browser ?? (await launchBrowser());
  try {
    return await part(browser, app?.url ?? server.url);
  } finally {
    if (!app?.browser) await browser.close();
    server?.close();
  }
}

/** One build served and one Chromium, for every part of a quick run; close() ends both. */
export async function sharedApp() {
  const server = await serveStatic(await buildTemporaryApp('shading-lab-bench-app-'));
  const browser = await launchBrowser();
  return {
    browser,
    url: server.url,
    close: async () => {
      await browser.close();
      server.close();
    },
  };
}
