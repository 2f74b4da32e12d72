// npm run stress: every JS function of src/math and every GLSL function of shaders/ over extreme inputs.
// Prints a table; exits non-zero if any result is NaN, Inf or outside its documented range.
import { sweepJs } from '../tests/support/stress-sweep.js';
import { buildApp, launchBrowser, openPage, serveStatic } from '../tests/browser/harness.js';

const { rows, unclassified } = sweepJs();
const pad = (s, n) => String(s).padEnd(n);
console.log(`${pad('JS function', 44)}${pad('inputs', 8)}${pad('range', 18)}NaN  Inf  outside`);
for (const r of rows)
  console.log(
    [pad(r.name, 44), pad(r.inputs, 8), pad(`[${r.range.join(', ')}]`, 18), pad(r.nan, 5), pad(r.inf, 5)].join('') +
      `${r.outside}${r.worst ? `   e.g. ${JSON.stringify(r.worst)}` : ''}`,
  );
const jsBad = rows.reduce((s, r) => s + r.nan + r.inf + r.outside, 0);
if (unclassified.length)
  console.log(`\nUnclassified exports (add them to tests/support/stress-domains.js): ${unclassified.join(', ')}`);

// GLSL: the parity grids are stress grids; count what the GPU returned outside the range
const server = await serveStatic(await buildApp());
const browser = await launchBrowser();
const page = await openPage(browser, server.url, 'parity.html');
await page.waitForSelector('#parity-summary', { timeout: 120_000 });
const gl = await page.evaluate(() =>
  globalThis.__shadingLab.parity.map((r) => ({ name: r.name, count: r.count, invalid: r.invalid })),
);
await browser.close();
server.close();
console.log(`\n${pad('GLSL function', 46)}${pad('inputs', 8)}NaN/Inf/outside`);
for (const r of gl) console.log(`${pad(r.name, 46)}${pad(r.count, 8)}${r.invalid}`);
const glBad = gl.reduce((s, r) => s + r.invalid, 0);
console.log(
  `\nJS: ${rows.length} functions, ${rows.reduce((s, r) => s + r.inputs, 0)} evaluations, ${jsBad} bad. GLSL: ` +
    `${gl.length} functions, ${gl.reduce((s, r) => s + r.count, 0)} inputs, ${glBad} bad.`,
);
process.exit(jsBad + glBad + unclassified.length ? 1 : 0);
