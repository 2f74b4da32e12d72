// Compile only what is shown, once: one program per key, made on first use and kept. The key is the set of
// #define switches, and for a program that holds chunks of its own (a user's term) the name of those chunks too
// (`own.key`: the code), so every view keeps its programs the same way (shader-builder.js builds them).

/** The cache key of a set of switches: its entries in name order, so the order they were written in is irrelevant. */
export const definesKey = (defines) =>
  Object.keys(defines)
    .sort()
    .map((name) => `${name}=${defines[name]}`)
    .join(';');

/**
 * The key of the program of `defines`, with chunks of its own named `own.key` or none.
 * @param {Record<string, unknown>} defines
 * @param {{ key: string } | undefined | null | false} [own]
 */
export const programKey = (defines, own) => `${own ? own.key : ''}\u0000${definesKey(defines)}`;

/**
 * `get(defines, own?)` returns the program `make(defines, own)` made for this key, making it the first time;
 * `has(defines, own?)` says whether it is made; `keepOnly(keep)` disposes of the programs with chunks of their
 * own for which `keep(key, own)` is false (code no longer drawn); `dispose()` disposes of every program made.
 * @template {{ key: string }} O
 * @template P
 * @param {(defines: Record<string, unknown>, own?: O) => P & { dispose(): void }} make
 */
export function createProgramCache(make) {
  /** @type {Map<string, { program: P & { dispose(): void }, own?: O }>} */
  const programs = new Map();
  return {
    /** @param {Record<string, unknown>} defines @param {O} [own] */
    get(defines, own) {
      const key = programKey(defines, own);
      let entry = programs.get(key);
      if (!entry) programs.set(key, (entry = { program: make(defines, own || undefined), own: own || undefined }));
      return entry.program;
    },
    /** @param {Record<string, unknown>} defines @param {O} [own] */
    has: (defines, own) => programs.has(programKey(defines, own)),
    /** @param {(key: string, own: O) => boolean} keep */
    keepOnly(keep) {
      for (const [key, entry] of programs)
        if (entry.own && !keep(key, entry.own)) {
          entry.program.dispose();
          programs.delete(key);
        }
    },
    get size() {
      return programs.size;
    },
    dispose() {
      programs.forEach((entry) => entry.program.dispose());
      programs.clear();
    },
  };
}
