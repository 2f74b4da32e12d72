// @ts-check
// A widget's own program around a user-written term (a sphere, the lab's shading) compiled with raw WebGL2 before
// three.js sees it: code that ran in the checks' program may still clash with a name of the widget's program. The
// guard keeps the last code that compiled there drawing and says why the new one does not.
import { compileCustom } from './compile.js';

const KEEP = 16; // verdicts remembered (a program per variant of defines; typing makes new code each pause)

/** @param {() => any} getRenderer  the three.js renderer the program is drawn with */
export function createCompileGuard(getRenderer) {
  /** @type {Map<string, { line: number, message: string }[]>} */
  const verdicts = new Map();
  /** @type {string | null} */
  let lastGood = null;

  /** @param {string} source */
  function errorsOf(source) {
    const known = verdicts.get(source);
    if (known) return known;
    const { errors } = compileCustom(getRenderer(), source);
    if (getRenderer().getContext().isContextLost()) return errors; // not a verdict on the code
    verdicts.set(source, errors);
    if (verdicts.size > KEEP) verdicts.delete(verdicts.keys().next().value ?? '');
    return errors;
  }

  return {
    /**
     * The code to draw with: `code` when each of its `sources(code)` compiles, else the last code that did (null
     * when none did yet), and the problems of `code`.
     * @param {string} code
     * @param {(code: string) => string[]} sources  the fragment sources of the programs drawn with it
     * @returns {{ code: string | null, problems: { line: number, message: string }[] }}
     */
    pick(code, sources) {
      const problems = sources(code).flatMap(errorsOf);
      if (!problems.length) lastGood = code;
      return { code: problems.length ? lastGood : code, problems };
    },
  };
}
