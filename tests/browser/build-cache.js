// The browser tests' build, skipped when dist/ was made from the same inputs (a run of one test file built the
// app every time: 35 to 53 s at a load average of 15 to 22, longer than many a file's tests). A clean clone or a CI
// checkout has no record, so it builds; SHADING_LAB_REBUILD=1 builds whatever the record says.
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, sep } from 'node:path';
import { ROOT, buildApp } from './harness.js';

/**
 * What the build reads, relative to ROOT: the app, its shaders and static files, the pages, the build's config
 * and the installed packages (npm rewrites node_modules/.package-lock.json on every install), and any .env file.
 */
const inputs = () => [
  'src',
  'shaders',
  'public',
  'vite.config.js',
  'package.json',
  'node_modules/.package-lock.json',
  ...readdirSync(ROOT).filter((name) => name.endsWith('.html') || name.startsWith('.env')),
];
const RECORD = join(ROOT, 'node_modules/.cache/shading-lab/browser-build.json');

/** Every file under `path` (a file or a folder of ROOT), sorted. */
function files(path) {
  const full = join(ROOT, path);
  if (!existsSync(full)) return [];
  if (!statSync(full).isDirectory()) return [path];
  return readdirSync(full)
    .sort()
    .flatMap((name) => files(join(path, name)));
}

/** One hash of the inputs' names and contents, and of the build's VITE_ variables. */
function inputHash(paths) {
  const hash = createHash('sha256');
  for (const path of paths) hash.update(`${path}\0`).update(readFileSync(join(ROOT, path))).update('\0');
  const env = Object.entries(process.env).filter(([k]) => k.startsWith('VITE_'));
  return hash.update(JSON.stringify(env.sort())).digest('hex');
}

/** The built files of `dir` with their sizes and times: a build or an edit since the record shows there. */
const outputs = (dir) =>
  files(relative(ROOT, dir)).map((path) => {
    const { size, mtimeMs } = statSync(join(ROOT, path));
    return `${path} ${size} ${mtimeMs}`;
  });

/**
 * Counts in `verdict` the modules the build read and those outside `paths` and node_modules (a module from elsewhere
 * would go unseen by the hash). A Vite plugin, given to buildApp.
 */
function readOnly(paths, verdict) {
  const held = (file) => paths.some((p) => file === p || file.startsWith(p + sep));
  return {
    name: 'shading-lab-build-inputs',
    generateBundle(_, bundle) {
      const read = Object.values(bundle).flatMap((chunk) => chunk.moduleIds ?? []);
      const stray = read
        .map((id) => id.split('?')[0])
        .filter((file) => file.startsWith(ROOT + sep) && existsSync(file))
        .map((file) => relative(ROOT, file))
        .filter((file) => !file.startsWith(`node_modules${sep}`) && !held(file));
      verdict.read += read.length;
      verdict.stray.push(...stray);
    },
  };
}

/** Builds the app into dist/ unless the record says that dist/ holds the build of the present inputs; its folder. */
export async function buildOnce() {
  const dir = join(ROOT, 'dist');
  const roots = inputs();
  const hash = inputHash(roots.flatMap(files));
  const record = existsSync(RECORD) ? JSON.parse(readFileSync(RECORD, 'utf8')) : null;
  const same = record?.hash === hash && record.outputs.join('\n') === outputs(dir).join('\n');
  if (same && process.env.SHADING_LAB_REBUILD !== '1') {
    console.log('dist/ is the build of the present sources: not built again (SHADING_LAB_REBUILD=1 builds it)');
    return dir;
  }
  const verdict = { read: 0, stray: [] };
  await buildApp(dir, { plugins: [readOnly(roots, verdict)] });
  mkdirSync(dirname(RECORD), { recursive: true });
  // a build that read a module the hash does not cover, or whose modules went unseen, is not recorded: built again
  const known = verdict.read > 0 && verdict.stray.length === 0;
  writeFileSync(RECORD, known ? JSON.stringify({ hash, outputs: outputs(dir) }) : 'null');
  return dir;
}
