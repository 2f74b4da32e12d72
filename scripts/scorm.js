// `npm run scorm -- SET.json OUT.zip`: a SCORM 1.2 package of an exercise set (one exercise, a list, or an index
// like public/exercises/index.json, optionally with "title" and "passMark" in percent). The zip holds the whole
// built app (dist/, built first if missing), the set as one file, a launch page and imsmanifest.xml. A set that
// fails the validator is refused with its messages and exit code 1.
import { existsSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { zipSync } from 'fflate';
import { launchPage, scormManifest } from '../src/exercises/scorm/manifest.js';
import { setFingerprint } from '../src/exercises/scorm/suspend.js';

const ROOT = resolve(import.meta.dirname, '..');
export const SET_PATH = 'set/exercises.json';
export const LAUNCH = 'scorm-launch.html';

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

/** The set's exercises as raw objects, in order, from what was read (an index's file names replaced by files). */
function rawList(json, baseUrl, raws) {
  const list = Array.isArray(json) ? json : Array.isArray(json?.exercises) ? json.exercises : [json];
  return list.map((item) => (typeof item === 'string' ? raws.get(new URL(item, baseUrl).href) : item));
}

/** Problems with the package's own fields (title, passMark) of an index. */
function packageFields(json) {
  const index = json && typeof json === 'object' && !Array.isArray(json) && Array.isArray(json.exercises);
  const title = index && typeof json.title === 'string' && json.title.trim() ? json.title.trim() : null;
  const mark = index ? json.passMark : undefined;
  const bad = mark !== undefined && !(typeof mark === 'number' && mark >= 0 && mark <= 100);
  return {
    title,
    mastery: mark ?? null,
    errors: bad ? [`passMark: ${JSON.stringify(mark)} is not a percentage 0…100`] : [],
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
  const { exercises, problems } = await validate.readExerciseSet(json, {
    source,
    baseUrl,
    schemaOf: validate.schemaOf,
    load: fileLoader(raws),
  });
  const fields = packageFields(json);
  const errors = [...problems.flatMap((p) => p.errors.map((e) => `${p.source}: ${e}`)), ...fields.errors];
  if (!exercises.length && !errors.length) errors.push(`${source} holds no exercises`);
  if (errors.length) return { errors };
  const title = fields.title ?? (exercises.length === 1 ? exercises[0].title : 'Shading Lab exercises');
  const set = { title, exercises: rawList(json, baseUrl, raws) };
  const entries = {};
  for (const f of filesUnder(dist)) entries[f] = readFileSync(join(dist, f));
  const text = (s) => new TextEncoder().encode(s);
  entries[SET_PATH] = text(JSON.stringify(set, null, 2));
  entries[LAUNCH] = text(launchPage({ title, set: SET_PATH }));
  const identifier = `shading-lab-${setFingerprint(exercises.map((e) => e.id))}`;
  const files = Object.keys(entries).sort();
  entries['imsmanifest.xml'] = text(
    scormManifest({ identifier, title, launch: LAUNCH, files, mastery: fields.mastery }),
  );
  const zip = zipSync(entries, { level: 6 });
  writeFileSync(outFile, zip);
  return { bytes: zip.length, files: files.length + 1, exercises: exercises.length };
}

/** Validation through Vite's module runner: the widgets' schemas import CSS, which plain Node cannot. */
async function viteValidator() {
  const { createServer, createServerModuleRunner } = await import('vite');
  const server = await createServer({
    root: ROOT,
    logLevel: 'warn',
    configFile: false,
    server: { middlewareMode: true, hmr: false, ws: false },
  });
  const runner = createServerModuleRunner(server.environments.ssr, { hmr: false });
  const { readExerciseSet } = await runner.import('/src/exercises/load.js');
  const { WIDGETS } = await runner.import('/src/widgets/registry.js');
  const schemaOf = async (name) => (Object.hasOwn(WIDGETS, name) ? (await WIDGETS[name].load()).widget.schema : null);
  return { readExerciseSet, schemaOf, close: async () => (await runner.close(), await server.close()) };
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
