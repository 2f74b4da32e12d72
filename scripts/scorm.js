// `npm run scorm -- SET.json OUT.zip`: a SCORM 1.2 package of an exercise set (one exercise, a list, or an index
// like public/exercises/index.json, optionally with "title" and "passMark" in percent). The zip holds the whole
// built app (dist/, built first if missing), the set as one file, a launch page and imsmanifest.xml. A set that
// fails the validator is refused with its messages and exit code 1.
import { existsSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { LAUNCH, SET_PATH, buildPackage, packageTitle, rawList } from '../src/exercises/scorm/package.js';
import { viteModules } from './vite-modules.js';

const ROOT = resolve(import.meta.dirname, '..');
export { LAUNCH, SET_PATH };

const filesUnder = (dir) =>
  readdirSync(dir, { recursive: true })
    .map(String)
    .filter((f) => statSync(join(dir, f)).isFile())
    .map((f) => f.split('\\').join('/'))
    .sort();

/** Reads a file: URL as the loader of src/exercises/load.js would fetch it, keeping each raw entry. */
function fileLoader(raws) {
  return async (url) => {
    try {
      const json = JSON.parse(readFileSync(fileURLToPath(url), 'utf8'));
      raws.set(url, json);
      return { json };
    } catch (e) {
      return { error: `could not be read (${e.message})` };
    }
  };
}

/**
 * Writes the package. validate: { readExerciseSet, schemaOf } (src/exercises/load.js and the widgets' schemas).
 * Returns { errors } (nothing written) or { bytes, files, exercises }.
 */
export async function packageSet({ setFile, outFile, dist, validate }) {
  const source = basename(setFile);
  let json;
  try {
    json = JSON.parse(readFileSync(setFile, 'utf8'));
  } catch (e) {
    return { errors: [`${source} could not be read as JSON (${e.message})`] };
  }
  const baseUrl = pathToFileURL(resolve(setFile)).href;
  const raws = new Map();
  const got = await validate.readExerciseSet(json, {
    source,
    baseUrl,
    schemaOf: validate.schemaOf,
    load: fileLoader(raws),
  });
  const { exercises, problems, title, passMark } = got;
  const errors = problems.flatMap((p) => p.errors.map((e) => `${p.source}: ${e}`));
  if (!exercises.length && !errors.length) errors.push(`${source} holds no exercises`);
  if (errors.length) return { errors };
  const app = {};
  for (const f of filesUnder(dist)) app[f] = readFileSync(join(dist, f));
  const raw = rawList(json, baseUrl, raws);
  const { zip, files } = buildPackage({ app, exercises, raw, title: packageTitle(title, exercises), passMark });
  writeFileSync(outFile, zip);
  return { bytes: zip.length, files, exercises: exercises.length };
}

/** Validation through Vite's module runner: the widgets' schemas import CSS, which plain Node cannot. */
async function viteValidator() {
  const runner = await viteModules();
  const { readExerciseSet } = await runner.import('/src/exercises/load.js');
  const { WIDGETS } = await runner.import('/src/widgets/registry.js');
  const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
  return { readExerciseSet, schemaOf, close: runner.close };
}

async function main([setFile, outFile]) {
  if (!setFile || !outFile) {
    console.error('usage: npm run scorm -- SET.json OUT.zip');
    return 2;
  }
  const started = Date.now();
  const dist = join(ROOT, 'dist');
  if (!existsSync(join(dist, 'exercises.html'))) {
    console.log('dist/ has no built app: building it first (npm run build)…');
    const { build } = await import('vite');
    await build({ root: ROOT, logLevel: 'warn' });
  }
  const validate = await viteValidator();
  try {
    const got = await packageSet({ setFile, outFile, dist, validate });
    if (got.errors) {
      console.error(`${setFile} cannot be exported:\n${got.errors.map((e) => `  - ${e}`).join('\n')}`);
      return 1;
    }
    const kb = (got.bytes / 1024).toFixed(0);
    const s = ((Date.now() - started) / 1000).toFixed(1);
    console.log(`${outFile}: ${got.exercises} exercises, ${got.files} files, ${kb} kB, in ${s} s`);
    return 0;
  } finally {
    await validate.close();
  }
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url))
  process.exitCode = await main(process.argv.slice(2));
