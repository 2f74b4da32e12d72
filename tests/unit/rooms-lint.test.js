// The rooms of docs/architecture.md ("Boundaries") as the lint enforces them: the table's "may import" column is
// the ROOMS list of eslint.config.js, and ESLint itself, run on a file in each room that imports every other room
// (and bench/, tests/, scripts/), reports no-restricted-imports on exactly the imports the table refuses.
import { readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { ESLint } from 'eslint';
import { describe, expect, it } from 'vitest';
import { ROOMS } from '../../eslint.config.js';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const OUTSIDE = ['bench', 'tests', 'scripts'];

/** The Boundaries table: room folder → the rooms it may import, as written in the doc. */
function documentedRooms() {
  const doc = readFileSync(join(ROOT, 'docs/architecture.md'), 'utf8');
  const table = doc.slice(doc.indexOf('## Boundaries'), doc.indexOf('## The widget contract'));
  const rows = [...table.matchAll(/^\| `(src\/[\w/]+)` \| ([^|]*) \|/gm)];
  return rows.map(([, files, may]) => ({ files, may: [...may.matchAll(/`(\w+)`/g)].map((m) => m[1]) }));
}

// Every import target: each room's folder and what sits outside src/.
const TARGETS = [...ROOMS.map((r) => ({ room: r.room, dir: r.files })), ...OUTSIDE.map((o) => ({ room: o, dir: o }))];

/** Lints a probe file in `files` that imports one module of every other room; returns the rooms refused. */
async function refusedFrom(eslint, files) {
  const others = TARGETS.filter((t) => t.dir !== files);
  const code = others.map((t, i) => `import x${i} from '${relative(files, t.dir)}/probe.js';\n`).join('');
  const [result] = await eslint.lintText(`${code}export default [${others.map((_, i) => `x${i}`)}];\n`, {
    filePath: join(ROOT, files, 'rooms-lint-probe.js'),
  });
  const lines = result.messages.filter((m) => m.ruleId === 'no-restricted-imports').map((m) => m.line);
  return lines.map((line) => others[line - 1].room).sort();
}

describe('the rooms: docs/architecture.md, eslint.config.js and what ESLint reports', () => {
  it("the doc's Boundaries table is the config's ROOMS list", () => {
    expect(documentedRooms()).toEqual(ROOMS.map(({ files, may }) => ({ files, may })));
  });

  it('each room may import exactly the rooms the table lists: every other import fails the lint', async () => {
    const eslint = new ESLint({ cwd: ROOT });
    for (const { files, may } of ROOMS) {
      const refused = TARGETS.filter((t) => t.dir !== files && !may.includes(t.room)).map((t) => t.room);
      expect(await refusedFrom(eslint, files), `imports refused in ${files}`).toEqual(refused.sort());
    }
  });
});
