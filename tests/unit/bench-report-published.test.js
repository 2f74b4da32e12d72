// The performance page reads the bench's report from its own room (src/pages/data/bench-report.json, copied by
// bench/publish-report.js): the copy must be the report bench/results/latest.json holds, byte for byte, or the
// page shows figures the docs (written from latest.json by bench/readme-tables.js) do not.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { PUBLISHED, REPORT } from '../../bench/publish-report.js';

describe('the published bench report', () => {
  it('is bench/results/latest.json as the bench wrote it (npm run bench:publish brings it up to date)', () => {
    expect(readFileSync(PUBLISHED, 'utf8')).toBe(readFileSync(REPORT, 'utf8'));
  });
});
