// Compile only what is shown, once: one program per set of #define switches, made on first use and kept.

/** The cache key of a set of switches: its entries in name order, so the order they were written in is irrelevant. */
export const definesKey = (defines) =>
  Object.keys(defines)
    .sort()
    .map((name) => `${name}=${defines[name]}`)
    .join(';');

/**
 * `get(defines)` returns the program `make(defines)` made for these switches, making it the first time;
 * `has(defines)` says whether it is made; `dispose()` disposes of every program made.
 * @template P
 * @param {(defines: Record<string, unknown>) => P & { dispose(): void }} make
 */
export function createProgramCache(make) {
  const programs = new Map();
  return {
    get(defines) {
      const key = definesKey(defines);
      if (!programs.has(key)) programs.set(key, make(defines));
      return programs.get(key);
    },
    has: (defines) => programs.has(definesKey(defines)),
    get size() {
      return programs.size;
    },
    dispose() {
      programs.forEach((program) => program.dispose());
      programs.clear();
    },
  };
}
