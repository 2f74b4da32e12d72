// The counts of issue 27's note, from a command: `node scripts/house-counts.js [DIR]` (DIR: a checkout, default
// this one; run it on two checkouts for before and after). Each line says what it counts.
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import { ESLint } from 'eslint';

const root = resolve(process.argv[2] ?? '.');
/** The files of `dirs` git tracks, or, in a tree that is no checkout (a `git archive`), every file under them. */
function filesOf(dirs) {
  try {
    const opts = { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] };
    return execFileSync('git', ['ls-files', ...dirs], opts).split('\n');
  } catch {
    return dirs.flatMap((d) => readdirSync(join(root, d), { recursive: true }).map((f) => join(d, f)));
  }
}
const tracked = filesOf(['src', 'bench']).filter((f) => f.endsWith('.js') && !f.endsWith('.data.js'));
const text = (f) => readFileSync(join(root, f), 'utf8');
const code = tracked;

// files a new anisotropic term needs: the test's family modules (its vi.doMock targets) and the GLSL files of its
// functions (its CHUNKS), beside the JS functions it writes in place of a src/math file
const ADD_TEST = 'tests/unit/add-an-anisotropic-term.test.js';
if (existsSync(join(root, ADD_TEST))) {
  const addTest = text(ADD_TEST);
  const mocked = [...new Set([...addTest.matchAll(/vi\.doMock\('([^']+)'/g)].map((m) => m[1]))];
  const glsl = [...new Set([...addTest.matchAll(/'([\w-]+\.glsl)':/g)].map((m) => m[1]))];
  console.log(`files to add an anisotropic D and V (the test's): ${mocked.length + glsl.length + 1}`);
  console.log(`  ${[...mocked, ...glsl, 'one src/math file for the two JS functions'].join(', ')}`);
} else console.log(`files to add an anisotropic D and V: no ${ADD_TEST} in this tree to show it`);

const lines = code.filter((f) => f.startsWith('src/')).map((f) => [f, text(f).split('\n').length - 1]);
const [bigFile, bigLines] = lines.sort((a, b) => b[1] - a[1])[0];
console.log(`largest file in src (data tables *.data.js aside): ${bigFile}, ${bigLines} lines`);

// every function's length as the house's lint rule counts it (blank lines and comments skipped)
const eslint = new ESLint({
  cwd: root,
  overrideConfig: {
    rules: { 'max-lines-per-function': ['error', { max: 1, skipBlankLines: true, skipComments: true }] },
  },
});
const results = await eslint.lintFiles(['src']);
const sizes = results.flatMap((r) =>
  r.messages
    .filter((m) => m.ruleId === 'max-lines-per-function')
    .map((m) => [`${relative(root, r.filePath)}:${m.line}`, Number(m.message.match(/\((\d+)\)/)[1])]),
);
const [bigFn, fnLines] = sizes.sort((a, b) => b[1] - a[1])[0];
console.log(`largest function in src: ${bigFn}, ${fnLines} code lines`);

// a room importing what its rule refuses (eslint.config.js's ROOMS), as the repository's own lint finds them
const upward = results.flatMap((r) => r.messages.filter((m) => m.ruleId === 'no-restricted-imports'));
console.log(`upward imports (lint's room rules) in src: ${upward.length}`);

const BUILD = /new (THREE\.)?(Raw)?ShaderMaterial\(|\.createProgram\(/;
const builders = code.filter((f) => f !== 'src/core/gpu/shader-builder.js' && BUILD.test(text(f)));
console.log(`places that build a shader outside src/core/gpu/shader-builder.js (src, bench): ${builders.length}`);
if (builders.length) console.log(`  ${builders.join(', ')}`);

// a cache of programs: a module that keeps programs it makes in a Map named for programs or a cache
const CACHE = /\b\w*(program|cache)\w*\s*=\s*new Map\(/i;
const caches = code.filter(
  (f) => CACHE.test(text(f)) && /buildShader\(|ShaderMaterial\(|createProgram\(|make\(/.test(text(f)),
);
console.log(`program caches (src, bench): ${caches.length} (${caches.join(', ')})`);

const dup = execFileSync('duplicates', ['--min-lines', '12', '--most', '200', '--seconds', '300'], {
  cwd: root,
  encoding: 'utf8',
});
console.log(`duplicates, pairs of >= 12 lines (the duplicates tool): ${dup.split('\n')[0]}`);
