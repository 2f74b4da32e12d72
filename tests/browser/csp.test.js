// The Content-Security-Policy of the built site (vite.config.js): present on every page the build wrote, strict
// for scripts, and enforced by the browser; every page runs under it with no violation, no console error and no
// page error. And, on the same visit, once every view of a page has drawn, the page draws nothing while idle.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { baseUrl, launchBrowser } from './helpers.js';
import { BUILT, POLICY_PAGES, openUnderPolicy } from './under-policy.js';
import { expectIdle } from './idle.js';

let browser;
beforeAll(async () => {
  browser = await launchBrowser();
});
afterAll(async () => {
  await browser?.close();
});

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
      const page = await openUnderPolicy(browser, 'embed.html?w=fresnel-zones');
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
});

// every page is checked for drawing nothing once idle but these: the gallery's and the wall's views are frames
// and tiles that context-budget.test.js follows; the embed's widget is fresnel.html's; the data: set, the exercises'
const IDLE_ELSEWHERE = /^(gallery|wall)\.html|^embed\.html|^exercises\.html\?src=/;

describe('Content-Security-Policy, and idle pages draw nothing', () => {
  for (const path of POLICY_PAGES) {
    const idle = !IDLE_ELSEWHERE.test(path) ? '; once every view has drawn, no draw call over 2 s' : '';
    const name = path.replace(/src=.*/, 'src=data:…');
    it(`${name} runs under the policy: no violation, no console error${idle}`, async () => {
      const page = await openUnderPolicy(browser, path);
      if (idle) await expectIdle(page);
      expect(await page.evaluate(() => window.__csp ?? [])).toEqual([]);
      expect(page.errors).toEqual([]);
      if (path.startsWith('exercises.html?src=')) {
        expect(await page.$eval('#exercise h2', (h) => h.textContent)).toBe('A set from a data: URL');
      }
      await page.close();
    }, 240_000); // room for the waits inside: a page that never goes quiet must fail on its draw calls, not here
  }
});
