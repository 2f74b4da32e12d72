// Reads a set of exercises: one exercise object, a list of them, or an index { "exercises": [file names
// relative to the index, or objects] }, from a URL or from a dropped file's text. Never throws: every
// problem comes back as { source, errors } next to the exercises that are fine.
import { showValue } from '../core/framework/state.js';
import { validateExercise, validateSetFields } from './validate.js';

// An exercise file is a few kB; a set is refused past these, before it is read into memory.
export const MAX_SET_BYTES = 1024 * 1024;
export const MAX_SET_ENTRIES = 200;
const LIMIT = `${MAX_SET_BYTES.toLocaleString('en')} bytes (1 MB)`;
const tooBig = (bytes) => `is ${bytes.toLocaleString('en')} bytes; the limit is ${LIMIT}`;

/** The body as text, or null past MAX_SET_BYTES (the read stops there, whatever the header claimed). */
async function cappedText(res) {
  const chunks = [];
  let size = 0;
  const reader = res.body.getReader();
  for (let part = await reader.read(); !part.done; part = await reader.read()) {
    size += part.value.length;
    if (size > MAX_SET_BYTES) {
      reader.cancel();
      return null;
    }
    chunks.push(part.value);
  }
  return new Blob(chunks).text();
}

/** fetch + JSON.parse with the failure said in words. Returns { json } or { error }. */
export async function fetchJson(url) {
  try {
    const res = await fetch(url);
    if (!res.ok) return { error: `could not be loaded (HTTP ${res.status})` };
    const claimed = Number(res.headers.get('content-length'));
    if (claimed > MAX_SET_BYTES) return { error: tooBig(claimed) };
    const text = res.body ? await cappedText(res) : '';
    return text === null ? { error: `is larger than the limit of ${LIMIT}` } : parseJson(text);
  } catch (e) {
    return { error: `could not be loaded (${e.message})` };
  }
}

export function parseJson(text) {
  try {
    return { json: JSON.parse(text) };
  } catch (e) {
    return { error: `is not valid JSON (${e.message})` };
  }
}

/** A short name for messages: the file name, or "data URL" for an inline set. */
function nameOf(url) {
  if (url.startsWith('data:')) return 'data URL';
  const name = new URL(url).pathname.split('/').pop() || url;
  try {
    return decodeURIComponent(name);
  } catch {
    return name; // a malformed escape (%E0) is shown as it is
  }
}

/**
 * Entries of a set and where each came from: [{ source, raw }] or [{ source, error }].
 * `json` was read from `baseUrl` (null for a dropped file, whose index entries cannot be fetched).
 */
async function entriesOf(json, source, baseUrl, load) {
  const list = Array.isArray(json) ? json : Array.isArray(json?.exercises) ? json.exercises : null;
  if (list?.length > MAX_SET_ENTRIES) {
    return [{ source, error: `lists ${list.length} exercises; a set holds at most ${MAX_SET_ENTRIES}` }];
  }
  if (Array.isArray(json)) return json.map((raw, i) => ({ source: `${source} #${i + 1}`, raw }));
  if (list) {
    return Promise.all(
      list.map(async (item, i) => {
        if (typeof item !== 'string') return { source: `${source} #${i + 1}`, raw: item };
        if (!baseUrl)
          return {
            source: item,
            error: 'is a file name, but a dropped index cannot fetch files: drop the exercise files themselves',
          };
        const got = await load(new URL(item, baseUrl).href);
        return got.error ? { source: item, error: got.error } : { source: item, raw: got.json };
      }),
    );
  }
  return [{ source, raw: json }];
}

/** Validates every entry; ids must be unique across the set. Returns { exercises, problems, title, passMark }. */
export async function readExerciseSet(json, { source, baseUrl = null, schemaOf, load = fetchJson }) {
  const exercises = [];
  const { title, passMark, errors: setErrors } = validateSetFields(json);
  const problems = setErrors.length ? [{ source, errors: setErrors }] : [];
  const seen = new Map();
  for (const entry of await entriesOf(json, source, baseUrl, load)) {
    if (entry.error) {
      problems.push({ source: entry.source, errors: [`${entry.source} ${entry.error}`] });
      continue;
    }
    const { exercise, errors } = await validateExercise(entry.raw, { schemaOf });
    if (exercise && seen.has(exercise.id))
      errors.push(`id: "${exercise.id}" is already used by ${seen.get(exercise.id)}`);
    if (errors.length) problems.push({ source: entry.source, errors });
    else {
      seen.set(exercise.id, entry.source);
      exercises.push({ ...exercise, source: entry.source });
    }
  }
  return { exercises, problems, title, passMark };
}

/** A set from a URL (resolved against the page). */
export async function loadExerciseSet(url, { schemaOf, load = fetchJson }) {
  const href = URL.canParse(url, location.href) && new URL(url, location.href).href;
  if (!href) return { exercises: [], problems: [{ source: 'src', errors: [`src: ${showValue(url)} is not a URL`] }] };
  const got = await load(href);
  const source = nameOf(href);
  if (got.error) return { exercises: [], problems: [{ source, errors: [`${source} ${got.error}`] }] };
  return readExerciseSet(got.json, { source, baseUrl: href, schemaOf, load });
}

/** A set from a chosen or dropped file; one over the size limit is refused by its size alone. */
export async function readExerciseFile(file, { schemaOf }) {
  const source = file.name;
  const got = file.size > MAX_SET_BYTES ? { error: tooBig(file.size) } : parseJson(await file.text());
  if (got.error) return { exercises: [], problems: [{ source, errors: [`${source} ${got.error}`] }] };
  return readExerciseSet(got.json, { source, schemaOf });
}
