// The Content-Security-Policy of the built site (vite.config.js): present on every page the build wrote, strict
// for scripts, enforced by the browser, and the app runs under it with no violation on any page.
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { baseUrl, launchBrowser, settle } from './helpers.js';
import { ROOT, openPage } from './harness.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/** Every violation in the page and its same-origin frames, in window.top.__csp (installed before any script). */
function recordViolations() {
  document.addEventListener('securitypolicyviolation', (e) => {
    (window.top.__csp ??= []).push(
      `${e.violatedDirective}: ${e.blockedURI || e.sample || '(inline)'} in ${location.pathname}`,
    );
  });
}

const BUILT = readdirSync(join(ROOT, 'dist'))
  .filter((f) => f.endsWith('.html'))
  .sort();
// when each page has finished what it does on load (its widgets mounted, its data drawn); run in the page
const READY = {
  'embed.html?w=fresnel-zones': () => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length === 1,
  'exercises.html': () => globalThis.__shadingLab?.exercise?.ready,
  'tour.html': () => globalThis.__shadingLab?.tour?.ready,
  'parity.html': () => globalThis.__shadingLab?.parity,
  'performance.html': () => globalThis.__shadingLab?.performance,
  'wall.html': () => Object.keys(globalThis.__shadingLab?.widgets ?? {}).length > 0,
};
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

/** The pages to run: every built HTML file, the embed with a widget, exercises with ?src=. */
const PAGES = [
  ...BUILT.filter((f) => f !== 'embed.html'),
  'embed.html?w=fresnel-zones',
  `exercises.html?src=${encodeURIComponent(`data:application/json,${JSON.stringify(ONE_EXERCISE)}`)}`,
];

async function openUnderPolicy(path) {
  const page = await openPage(browser, baseUrl(), path, {
    width: 1100,
    height: 800,
    beforeLoad: (p) => p.evaluateOnNewDocument(recordViolations),
  });
  const ready = READY[path.startsWith('embed.html') ? path : path.split('?')[0]] ?? chapterReady;
  if (ready) await page.waitForFunction(ready, { timeout: 60_000 });
  await settle(page, 800);
  return page;
}

describe('Content-Security-Policy', () => {
  it(
    'every built page carries the policy in a <meta> before its first script: ' + 'scripts from the app only, no eval',
    async () => {
      expect(BUILT.length).toBeGreaterThanOrEqual(17);
      const page = await browser.newPage();
      for (const file of BUILT) {
        await page.goto(new URL(file, baseUrl()).href, { waitUntil: 'domcontentloaded' });
        const { policy, beforeScripts } = await page.evaluate(() => {
          const meta = document.querySelector('meta[http-equiv="Content-Security-Policy"]');
          const first = document.querySelector('script');
          return {
            policy: meta?.content,
            beforeScripts: Boolean(
              meta && first && meta.compareDocumentPosition(first) & Node.DOCUMENT_POSITION_FOLLOWING,
            ),
          };
        });
        expect(policy, file).toMatch(/(^|; )script-src 'self'(;|$)/);
        expect(policy, file).toMatch(/(^|; )worker-src 'self'(;|$)/); // explicit, should script-src ever loosen
        expect(policy, file).toMatch(/(^|; )default-src 'self'(;|$)/);
        expect(policy, file).toMatch(/(^|; )object-src 'none'(;|$)/);
        expect(policy, file).not.toMatch(/unsafe-eval|script-src[^;]*unsafe-inline|\*/);
        expect(beforeScripts, file).toBe(true);
        // only the exercises page fetches from other hosts (?src=); the rest only from their own origin
        expect(policy.match(/connect-src [^;]*/)[0], file).toBe(
          file === 'exercises.html' ? "connect-src 'self' https: data:" : "connect-src 'self'",
        );
      }
      await page.close();
    },
  );

  it(
    'the browser enforces it: an injected inline script, an inline handler, ' +
      'a string timer (eval) and a javascript: link do not run',
    async () => {
      const page = await openUnderPolicy('embed.html?w=fresnel-zones');
      // (eval called here directly would pass: DevTools runs this function outside the page's policy)
      const ran = await page.evaluate(async () => {
        const ran = [];
        window.__ran = (what) => ran.push(what);
        document.body.append(
          Object.assign(document.createElement('script'), { textContent: 'window.__ran("script")' }),
        );
        const img = document.createElement('img');
        img.setAttribute('onerror', 'window.__ran("handler")');
        img.src = 'data:,not-an-image';
        document.body.append(img);
        setTimeout('window.__ran("timer")', 0);
        const link = Object.assign(document.createElement('a'), { href: 'javascript:window.__ran("link")' });
        document.body.append(link);
        link.click();
        await new Promise((r) => setTimeout(r, 400));
        return ran;
      });
      expect(ran).toEqual([]);
      const violations = (await page.evaluate(() => window.__csp ?? [])).join('\n');
      expect(violations).toMatch(/script-src-elem: inline/); // the script, and the javascript: link
      expect(violations).toMatch(/script-src-attr: inline/);
      expect(violations).toMatch(/script-src: eval/);
      await page.close();
    },
  );

  for (const path of PAGES) {
    it(`${path.replace(/src=.*/, 'src=data:…')} runs under the policy: no violation, no console error`, async () => {
      const page = await openUnderPolicy(path);
      expect(await page.evaluate(() => window.__csp ?? [])).toEqual([]);
      expect(page.errors).toEqual([]);
      if (path.startsWith('exercises.html?src=')) {
        expect(await page.$eval('#exercise h2', (h) => h.textContent)).toBe('A set from a data: URL');
      }
      await page.close();
    });
  }
});
