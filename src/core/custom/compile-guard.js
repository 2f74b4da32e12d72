// @ts-check
// A widget's own program around a user-written term (a sphere, the lab's shading) compiled by three.js before the
// view draws it (compile.js): code that ran in the checks' program may still clash with a name of the widget's
// program. The guard keeps the last code that compiled there drawing and says why the new one does not. The
// programs of the code it passes are held until the next good code, so the view's materials, made from the same
// sources, take them over instead of compiling them again.
import { compileCustom } from './compile.js';

const KEEP = 16; // verdicts remembered (a program per variant of defines; typing makes new code each pause)

/**
 * @param {() => any} getRenderer  the three.js renderer the program is drawn with
 * @param {{ vertex?: string, offscreen?: boolean }} [drawn]  how the view draws it: its vertex program (a file of
 *   shaders/; the full-screen one when omitted) and whether into a render target
 */
export function createCompileGuard(getRenderer, drawn = {}) {
  /** @type {Map<string, { line: number, message: string }[]>} */
  const verdicts = new Map();
  /** @type {string | null} */
  let lastGood = null;
  /** @type {Map<string, () => void>} the compiled programs held, by source, with their release */
  let held = new Map();

  /** @param {string} source @param {Map<string, () => void>} fresh  where a newly compiled program is held */
  function errorsOf(source, fresh) {
    const known = verdicts.get(source);
    if (known) return known;
    const { errors, release } = compileCustom(getRenderer(), source, drawn);
    if (getRenderer().getContext().isContextLost()) return errors; // not a verdict on the code
    verdicts.set(source, errors);
    if (verdicts.size > KEEP) verdicts.delete(verdicts.keys().next().value ?? '');
    fresh.set(source, release);
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
      /** @type {Map<string, () => void>} */
      const fresh = new Map();
      const problems = sources(code).flatMap((source) => errorsOf(source, fresh));
      if (problems.length) fresh.forEach((release) => release());
      else {
        if (code !== lastGood) {
          held.forEach((release) => release());
          held = new Map();
        }
        fresh.forEach((release, source) => held.set(source, release));
        lastGood = code;
      }
      return { code: problems.length ? lastGood : code, problems };
    },
  };
}
