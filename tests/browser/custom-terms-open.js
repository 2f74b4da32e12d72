// The page of the custom-terms core (tests/browser/custom-terms.html), built into a directory of its own and
// served, with a browser open on it: what custom-terms.test.js and custom-d-aniso.test.js drive.
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { build } from 'vite';
import { ROOT, launchBrowser, openPage, serveStatic } from './harness.js';
import { WAIT_MS } from './helpers.js';

/** Builds and opens the page; resolves to { browser, server, page } once window.__customTerms is there. */
export async function openCustomTermsPage() {
  const outDir = mkdtempSync(join(tmpdir(), 'shading-lab-custom-terms-'));
  await build({
    root: ROOT,
    configFile: false,
    base: './',
    logLevel: 'warn',
    build: {
      outDir,
      emptyOutDir: true,
      chunkSizeWarningLimit: 4000, // three.js in one chunk: a test page, not a page of the app
      rollupOptions: { input: join(ROOT, 'tests/browser/custom-terms.html') },
    },
  });
  const server = await serveStatic(outDir);
  const browser = await launchBrowser();
  const page = await openPage(browser, server.url, 'tests/browser/custom-terms.html');
  await page.waitForFunction(() => window.__customTerms, { timeout: WAIT_MS });
  return { browser, server, page };
}
