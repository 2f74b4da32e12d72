// The time of a full grade of each shipped shader exercise, as the student waits for it: from pressing Check with
// the correct code in the editor to the feedback on the page (static check, compile, the GPU over the whole grid,
// read-back, the float64 references, the comparison, the plot). The first Check of an exercise compiles its
// program; the median is over the Checks after it. `node bench/custom-grade.js` prints the table.
import { join } from 'node:path';
import { ROOT, buildApp, launchBrowser, openPage, serveStatic } from '../tests/browser/harness.js';
import { SHADER_SOLUTIONS } from '../tests/browser/shader-solutions.js';

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** In the page: presses Check and resolves with the milliseconds until the feedback is graded. */
function timeCheck() {
  const feedback = document.querySelector('.exercise-feedback');
  return new Promise((resolve) => {
    const start = performance.now();
    const observer = new MutationObserver(() => {
      if (!/\b(ok|wrong)\b/.test(feedback.className)) return;
      observer.disconnect();
      requestAnimationFrame(() => resolve(performance.now() - start));
    });
    observer.observe(feedback, { attributes: true, attributeFilter: ['class'] });
    document.querySelector('.exercise-check').click();
  });
}

/** Puts `code` in the editor of the open exercise as a user would (select all, type). */
async function typeCode(page, code) {
  await page.click('.exercise-code .cm-content');
  await page.keyboard.down('Control');
  await page.keyboard.press('a');
  await page.keyboard.up('Control');
  await page.keyboard.sendCharacter(code);
}

/**
 * { runs, outDir, baseUrl, limit, browser } → rows { id, inputs, firstMs, medianMs, passed } per shader exercise (the
 * first `limit` of them). Without `baseUrl` it builds the app into outDir and serves it; without `browser` (a
 * launched Chromium, left open) it launches one of its own.
 */
export async function measureCustomGrade(options = {}) {
  const { runs = 5, outDir = join(ROOT, 'dist'), baseUrl, limit = Infinity, browser: shared } = options;
  const server = baseUrl ? null : await serveStatic(await buildApp(outDir));
  const browser = shared ?? (await launchBrowser());
  const rows = [];
  try {
    const page = await openPage(browser, baseUrl ?? server.url, 'exercises.html', { width: 1280, height: 1000 });
    for (const [id, { correct }] of Object.entries(SHADER_SOLUTIONS).slice(0, limit)) {
      await page.evaluate((i) => (location.hash = i), id);
      await page.waitForFunction(
        (i) => globalThis.__shadingLab?.exercise?.id === i && globalThis.__shadingLab.exercise.ready,
        {},
        id,
      );
      await typeCode(page, correct);
      const times = [];
      for (let i = 0; i <= runs; i++) times.push(await page.evaluate(timeCheck));
      const passed = await page.$eval('.exercise-feedback', (el) => el.classList.contains('ok'));
      const inputs = Number(
        (await page.$eval('.exercise-feedback p', (p) => p.textContent))
          .match(/all ([\d,]+) inputs/)?.[1]
          .replace(/,/g, ''),
      );
      rows.push({ id, inputs, firstMs: times[0], medianMs: median(times.slice(1)), passed });
    }
    await page.close();
  } finally {
    if (!shared) await browser.close();
    await server?.close();
  }
  return rows;
}

/** The rows as a text table. */
export function printCustomGrade(rows) {
  console.log('\nShader exercises, a full grade (Check to feedback), correct code:');
  console.log('exercise                     inputs   first (ms)   median (ms)   passed');
  for (const r of rows)
    console.log(
      `${r.id.padEnd(28)} ${String(r.inputs).padStart(6)} ${r.firstMs.toFixed(1).padStart(12)} ` +
        `${r.medianMs.toFixed(1).padStart(13)}   ${r.passed}`,
    );
}

if (process.argv[1] && import.meta.filename === process.argv[1]) {
  const outDir = process.argv.includes('--out') ? process.argv[process.argv.indexOf('--out') + 1] : undefined;
  printCustomGrade(await measureCustomGrade({ outDir }));
}
