// axe-core (Deque's accessibility engine) run over a page: WCAG 2.2 A and AA, violations only. Used by axe.test.js
// and, for the wall (whose twenty tiles context-budget.test.js mounts and scrolls through anyway), there.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const TAGS = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'];

/**
 * axe's violations in the page, one line each: rule, target selector, what to fix. Only violations are gathered
 * (resultTypes): the passes' nodes, which axe would otherwise collect for every rule, are never read.
 */
export async function axeViolations(page) {
  // DevTools runs it outside the page's policy, which forbids inline scripts; once a page (the tour's second check)
  if (!(await page.evaluate(() => 'axe' in globalThis))) await page.evaluate(AXE);
  return page.evaluate(async (tags) => {
    const options = { runOnly: { type: 'tag', values: tags }, iframes: false, resultTypes: ['violations'] };
    const result = await globalThis.axe.run(document, options);
    return result.violations.flatMap((v) =>
      v.nodes.map((n) => `${v.id} at ${n.target.join(' ')}: ${n.failureSummary.replace(/\s+/g, ' ')}`),
    );
  }, TAGS);
}
