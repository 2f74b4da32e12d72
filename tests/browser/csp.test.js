// The Content-Security-Policy of the built site (vite.config.js): present on every page the build wrote (read from
// dist/ in Node: the build of this run, made by global-setup.js), strict for scripts, and enforced by the browser.
// That every page runs under it with no violation is axe.test.js, on the same visit as its accessibility check.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { WAIT_MS, launchBrowser } from './helpers.js';
import { ROOT } from './harness.js';
import { BUILT, openUnderPolicy } from './under-policy.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

/**
 * A built page's policy <meta> (its content) and whether it comes before the page's first
 * <script>: read from the file as the parser meets it, start to end (no comment or template holds either here).
 */
function policyOf(file) {
  const html = readFileSync(join(ROOT, 'dist', file), 'utf8');
  const meta = /<meta\s+http-equiv="Content-Security-Policy"\s+content="([^"]*)"\s*\/?>/i.exec(html);
  const script = html.search(/<script[\s>]/i);
  return { policy: meta?.[1], beforeScripts: Boolean(meta && script >= 0 && meta.index < script) };
}

describe('Content-Security-Policy', () => {
  it(
    'every built page carries the policy in a <meta> before its first script: ' + 'scripts from the app only, no eval',
    () => {
      expect(BUILT.length).toBeGreaterThanOrEqual(17);
      for (const file of BUILT) {
        const { policy, beforeScripts } = policyOf(file);
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
    },
  );

  it(
    'the browser enforces it: an injected inline script, an inline handler, ' +
      'a string timer (eval) and a javascript: link do not run',
    async () => {
      const page = await openUnderPolicy(browser, 'embed.html?w=fresnel-zones');
      // (eval called here directly would pass: DevTools runs this function outside the page's policy)
      await page.evaluate(() => {
        const ran = (window.__ranList = []);
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
      });
      // the browser has refused all four (the script and the link, the handler, the timer's eval) once it has
      // reported them: then none of them can still run
      const refused = () =>
        page.evaluate(() => {
          const seen = (window.__csp ?? []).join('\n');
          return (
            seen.match(/script-src-elem: inline/g)?.length >= 2 && /script-src-attr/.test(seen) && /eval/.test(seen)
          );
        });
      await expect
        .poll(refused, { timeout: WAIT_MS })
        .toBe(true)
        .catch(() => {});
      expect(await page.evaluate(() => window.__ranList)).toEqual([]);
      const violations = (await page.evaluate(() => window.__csp ?? [])).join('\n');
      expect(violations).toMatch(/script-src-elem: inline/); // the script, and the javascript: link
      expect(violations).toMatch(/script-src-attr: inline/);
      expect(violations).toMatch(/script-src: eval/);
      await page.close();
    },
  );
});
