// @ts-check
// Compiles a program that holds a user-written term by three.js itself, before a view draws it: its failure is
// heard through three.js's error hook (shader-builder.js's compileShader), so a page with user code stays quiet,
// and the program three.js compiled is the one the view's material then draws with (no second compile beside
// it). The compiler's log lines of source string 1 (the user's code, after `#line 1 1`: assemble.js) are the
// user's own lines.
import { buildShader, compileShader } from '../gpu/shader-builder.js';
import { USER_SOURCE } from './assemble.js';

/** @typedef {{ line: number, message: string }} CompileError  line 0: not in the user's code */
/** @typedef {{ ok: boolean, errors: CompileError[], release(): void }} Compiled */

// ANGLE and the drivers write 'ERROR: 1:3: message' (source string : line)
const LOG_LINE = /^\s*(?:ERROR|error)\s*:\s*(\d+)\s*:\s*(\d+)\s*:\s*(.*)$/;

/**
 * The errors of a compiler log, each on the user's line when it is in source string 1.
 * @param {string} log
 * @returns {CompileError[]}
 */
export function logErrors(log) {
  return log
    .split('\n')
    .map((text) => text.trim())
    .filter((text) => text && !/^\s*WARNING/i.test(text))
    .map((text) => {
      const m = LOG_LINE.exec(text);
      if (!m) return { line: 0, message: text.replace(/^ERROR:\s*/, '') };
      const [, source, line, message] = m;
      if (Number(source) === USER_SOURCE) return { line: Number(line), message };
      return { line: 0, message: `in the program around your code: ${message}` };
    });
}

const nothing = () => {};

/**
 * Compiles `fragmentSource` (an assembled program) over the vertex program `vertex` with the renderer, as a view
 * draws it (`offscreen`: into a render target). `release()` lets the compiled program go (three.js keeps it while
 * a material of the same source uses it, so call it once the view's own material is made).
 * @param {any} renderer a THREE.WebGLRenderer
 * @param {string} fragmentSource
 * @param {{ vertex?: string, offscreen?: boolean }} [options]
 * @returns {Compiled}
 */
export function compileCustom(renderer, fragmentSource, { vertex, offscreen = false } = {}) {
  const gl = renderer.getContext();
  if (gl.isContextLost())
    return { ok: false, errors: [{ line: 0, message: 'the WebGL context is lost' }], release: nothing };
  const material = buildShader('custom', { source: fragmentSource, vertex });
  const release = () => material.dispose();
  const failed = compileShader(renderer, material, { offscreen });
  if (!failed) return { ok: true, errors: [], release };
  release();
  const errors = logErrors(failed.fragment || failed.vertex || failed.program);
  return {
    ok: false,
    errors: errors.length ? errors : [{ line: 0, message: 'the shader does not compile (no log)' }],
    release: nothing,
  };
}
