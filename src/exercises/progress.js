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
