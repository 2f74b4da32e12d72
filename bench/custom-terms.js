// The bench's part for user-written terms (issue 13): the time from an edit of a custom term to the redrawn
// widget (bench/custom-edit.js) and the time of a full grade of each shader exercise (bench/custom-grade.js),
// both on one build of the app. `npm run bench -- --only custom` runs this part alone.
import { buildTemporaryApp, inBrowser } from './browser-part.js';
import { measureCustomEdit } from './custom-edit.js';
import { measureCustomGrade, printCustomGrade } from './custom-grade.js';

/**
 * { edit: { medianMs, worstMs, edits, missed, editDelayMs }, grade: rows }, on the app built into BUILT_APP when set
 * (else a temporary folder); --quick: two edits (the code pasted in, not typed) and two exercises graded twice, in
 * one Chromium, to check the part runs. `app`: see inBrowser.
 */
export function measureCustomTerms({ quick = false, app } = {}) {
  return inBrowser(
    app,
    () => buildTemporaryApp('shading-lab-custom-'),
    async (browser, url) => {
      // quick: its figures are not read, so a short pause before the edits
      const edit = await measureCustomEdit({
        url,
        browser,
        edits: quick ? 2 : 20,
        paste: quick,
        pauseMs: quick ? 500 : 2000,
      });
      // quick: the grades in the same Chromium (a full run grades in a Chromium of their own, as before)
      const grade = quick
        ? await measureCustomGrade({ runs: 1, baseUrl: url, limit: 2, browser })
        : await measureCustomGrade({ runs: 5, baseUrl: url });
      return { edit, grade };
    },
  );
}

export function printCustomTerms({ edit, grade }) {
  console.log(
    `\nA user-written D in brdf-lobe, from a keystroke to the redrawn widget over ${edit.edits} edits: ` +
      `median ${edit.medianMs.toFixed(0)} ms, worst ${edit.worstMs.toFixed(0)} ms ` +
      `(of which ${edit.editDelayMs} ms is the pause the editor waits for typing to stop)`,
  );
  printCustomGrade(grade);
}
