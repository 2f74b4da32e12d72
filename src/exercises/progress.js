// Progress on the exercises, kept in localStorage: { [id]: { solved, attempts } }. A store that cannot be
// read or written (private mode, corrupt data) starts empty and the page still works for the session.
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
    /** Counts an attempt; a solved exercise stays solved. */
    record(id, ok) {
      const p = this.of(id);
      data[id] = { solved: p.solved || ok, attempts: p.attempts + 1 };
      save();
      return data[id];
    },
    reset() {
      data = {};
      try {
        storage.removeItem(KEY);
      } catch {
        // nothing stored
      }
    },
  };
}
