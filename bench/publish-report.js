// Publishes the bench's report to the app: the performance page (src/pages/performance.js) reads a copy in its own
// room, src/pages/data/bench-report.json, so that the app imports nothing from bench/. `npm run bench` publishes
// the report it writes to bench/results/latest.json; `npm run bench:publish` does it alone, after an edit by hand.
// tests/unit/bench-report-published.test.js checks that the two are the same.
import { copyFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
export const REPORT = join(ROOT, 'bench/results/latest.json');
export const PUBLISHED = join(ROOT, 'src/pages/data/bench-report.json');

export function publishReport() {
  copyFileSync(REPORT, PUBLISHED);
  return PUBLISHED;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) console.log(`Published ${publishReport()}`);
