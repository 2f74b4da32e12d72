// Progress on the exercises, kept in localStorage: { [id]: { solved, attempts } }. A store that cannot be
// read or written (private mode, corrupt data) starts empty and the page still works for the session.
// An attempt is one answer: the same answer checked again (Enter, then Check) is not counted twice.
const KEY = 'shading-lab.exercises.progress.v1';

function read(storage) {
  try {
    const data = JSON.parse(storage.getItem(KEY) ?? '{}');
    return data && typeof data === 'object' && !Array.isArray(data) ? data : {};
  } catch {
    return {};
  }
}

/** A Storage kept in memory only: progress for this page's life (a preview, a set the student loads in an LMS). */
export function memoryStorage() {
  let json = '{}';
  return { getItem: () => json, setItem: (_key, text) => void (json = text), removeItem: () => void (json = '{}') };
}

export function createProgress(storage = globalThis.localStorage) {
  let data = read(storage);
  const lastAnswer = new Map(); // id -> the last counted answer, this session
  const save = () => {
    try {
      storage.setItem(KEY, JSON.stringify(data));
    } catch {
      // not persisted; the session keeps it in memory
    }
  };
  return {
    of(id) {
      const entry = Object.hasOwn(data, id) ? data[id] : null; // an id like 'constructor' reads nothing inherited
      return { solved: Boolean(entry?.solved), attempts: Number(entry?.attempts) || 0 };
    },
    /**
     * Counts an attempt unless `answer` (a string: what was submitted) is the one counted last for `id`; a solved
     * exercise stays solved. Returns whether it was counted.
     */
    record(id, ok, answer) {
      if (answer !== undefined && lastAnswer.get(id) === answer) return false;
      if (answer !== undefined) lastAnswer.set(id, answer);
      const p = this.of(id);
      data[id] = { solved: p.solved || ok, attempts: p.attempts + 1 };
      save();
      return true;
    },
    /** Takes the entries of a progress file ({ id, solved, attempts }) whose id is in `ids`; returns how many. */
    load(entries, ids) {
      const taken = entries.filter((e) => ids.includes(e.id));
      for (const e of taken) data[e.id] = { solved: e.solved, attempts: e.attempts };
      lastAnswer.clear();
      save();
      return taken.length;
    },
    reset() {
      data = {};
      lastAnswer.clear();
      try {
        storage.removeItem(KEY);
      } catch {
        // nothing stored
      }
    },
  };
}

export const PROGRESS_FILE_TYPE = 'shading-lab-progress';
const MAX_NAME = 200;

/**
 * The progress file a student saves (for a course with no LMS): which exercises of the set are solved and in how
 * many attempts, with their titles and points, so that the lecturer's view needs nothing else. What a browser
 * recorded, not proof: a student can edit it.
 */
export function progressFile({ name = '', title = null, exercises, progress, saved = new Date() }) {
  return {
    type: PROGRESS_FILE_TYPE,
    version: 1,
    name: String(name).trim().slice(0, MAX_NAME),
    set: title,
    saved: saved.toISOString(),
    exercises: exercises.map((e) => ({ id: e.id, title: e.title, points: e.points ?? 1, ...progress.of(e.id) })),
  };
}

const isEntry = (e) =>
  e &&
  typeof e.id === 'string' &&
  typeof e.title === 'string' &&
  typeof e.solved === 'boolean' &&
  Number.isInteger(e.attempts) &&
  e.attempts >= 0 &&
  typeof e.points === 'number' &&
  e.points > 0;

/** A progress file's text read back: { file } or { error } in words. */
export function readProgressFile(text) {
  let json;
  try {
    json = JSON.parse(text);
  } catch (e) {
    return { error: `is not valid JSON (${e.message})` };
  }
  if (json?.type !== PROGRESS_FILE_TYPE || json.version !== 1)
    return { error: 'is not a Shading Lab progress file (saved with “Save my progress”)' };
  if (!Array.isArray(json.exercises) || !json.exercises.every(isEntry))
    return { error: 'has an exercise entry that is not { id, title, points, solved, attempts }' };
  const name = typeof json.name === 'string' ? json.name.slice(0, MAX_NAME) : '';
  const set = typeof json.set === 'string' ? json.set : null;
  const saved = typeof json.saved === 'string' && !Number.isNaN(Date.parse(json.saved)) ? json.saved : null;
  return { file: { name, set, saved, exercises: json.exercises } };
}
