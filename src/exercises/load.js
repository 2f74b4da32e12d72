// Reads a set of exercises: one exercise object, a list of them, or an index { "exercises": [file names
// relative to the index, or objects] }, from a URL or from a dropped file's text. Never throws: every
// problem comes back as { source, errors } next to the exercises that are fine.
import { validateExercise } from './validate.js';

/** fetch + JSON.parse with the failure said in words. Returns { json } or { error }. */
export async function fetchJson(url) {
  let res;
  try {
    res = await fetch(url);
  } catch (e) {
    return { error: `could not be loaded (${e.message})` };
  }
  if (!res.ok) return { error: `could not be loaded (HTTP ${res.status})` };
  return parseJson(await res.text());
}

export function parseJson(text) {
  try {
    return { json: JSON.parse(text) };
  } catch (e) {
    return { error: `is not valid JSON (${e.message})` };
  }
}

/** A short name for messages: the file name, or "data URL" for an inline set. */
const nameOf = (url) => (url.startsWith('data:') ? 'data URL' : decodeURIComponent(new URL(url).pathname.split('/').pop() || url));

/**
 * Entries of a set and where each came from: [{ source, raw }] or [{ source, error }].
 * `json` was read from `baseUrl` (null for a dropped file, whose index entries cannot be fetched).
 */
async function entriesOf(json, source, baseUrl, load) {
  if (Array.isArray(json)) return json.map((raw, i) => ({ source: `${source} #${i + 1}`, raw }));
  if (json && typeof json === 'object' && Array.isArray(json.exercises)) {
    return Promise.all(json.exercises.map(async (item, i) => {
      if (typeof item !== 'string') return { source: `${source} #${i + 1}`, raw: item };
      if (!baseUrl) return { source: item, error: 'is a file name, but a dropped index cannot fetch files: drop the exercise files themselves' };
      const got = await load(new URL(item, baseUrl).href);
      return got.error ? { source: item, error: got.error } : { source: item, raw: got.json };
    }));
  }
  return [{ source, raw: json }];
}

/** Validates every entry; ids must be unique across the set. Returns { exercises, problems }. */
export async function readExerciseSet(json, { source, baseUrl = null, schemaOf, load = fetchJson }) {
  const exercises = [];
  const problems = [];
  const seen = new Map();
  for (const entry of await entriesOf(json, source, baseUrl, load)) {
    if (entry.error) {
      problems.push({ source: entry.source, errors: [`${entry.source} ${entry.error}`] });
      continue;
    }
    const { exercise, errors } = await validateExercise(entry.raw, { schemaOf });
    if (exercise && seen.has(exercise.id)) errors.push(`id: "${exercise.id}" is already used by ${seen.get(exercise.id)}`);
    if (errors.length) problems.push({ source: entry.source, errors });
    else {
      seen.set(exercise.id, entry.source);
      exercises.push({ ...exercise, source: entry.source });
    }
  }
  return { exercises, problems };
}

/** A set from a URL (resolved against the page). */
export async function loadExerciseSet(url, { schemaOf, load = fetchJson }) {
  const href = new URL(url, location.href).href;
  const got = await load(href);
  const source = nameOf(href);
  if (got.error) return { exercises: [], problems: [{ source, errors: [`${source} ${got.error}`] }] };
  return readExerciseSet(got.json, { source, baseUrl: href, schemaOf, load });
}
