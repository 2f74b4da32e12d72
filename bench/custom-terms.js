// The bench's part for user-written terms (issue 13): the time from an edit of a custom term to the redrawn
// widget (bench/custom-edit.js) and the time of a full grade of each shader exercise (bench/custom-grade.js),
// both on one build of the app. `npm run bench -- --only custom` runs this part alone.
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { buildApp, launchBrowser, serveStatic } from '../tests/browser/harness.js';
import { measureCustomEdit } from './custom-edit.js';
import { measureCustomGrade, printCustomGrade } from './custom-grade.js';

/** { edit: { medianMs, worstMs, edits, missed, editDelayMs }, grade: rows }; --quick: a few edits and one grade. */
export async function measureCustomTerms({ quick = false } = {}) {
  const server = await serveStatic(await buildApp(mkdtempSync(join(tmpdir(), 'shading-lab-custom-'))));
  const browser = await launchBrowser();
  try {
    const edit = await measureCustomEdit({ url: server.url, browser, edits: quick ? 3 : 20 });
    const grade = await measureCustomGrade({ runs: quick ? 1 : 5, baseUrl: server.url });
    return { edit, grade };
  } finally {
    await browser.close();
    server.close();
  }
}

export function printCustomTerms({ edit, grade }) {
  console.log(
    `\nA user-written D in brdf-lobe, from a keystroke to the redrawn widget over ${edit.edits} edits: ` +
      `median ${edit.medianMs.toFixed(0)} ms, worst ${edit.worstMs.toFixed(0)} ms ` +
      `(of which ${edit.editDelayMs} ms is the pause the editor waits for typing to stop)`,
  );
  printCustomGrade(grade);
}
