// @ts-check
// Compiles a fragment shader that holds a user-written term with raw WebGL2, before three.js ever sees it: three.js
// prints a failed compile to the console, and a page with user code must stay quiet. The compiler's log lines of
// source string 1 (the user's code, after `#line 1 1`: assemble.js) are the user's own lines.
import { USER_SOURCE } from './assemble.js';

/** @typedef {{ line: number, message: string }} CompileError  line 0: not in the user's code */

// what three.js puts before a GLSL3 ShaderMaterial's own code, as far as the compiler's rules go
const PREFIX = '#version 300 es\nprecision highp float;\nprecision highp int;\n';
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

/**
 * Compiles `fragmentSource` (an assembled program, without #version) with the renderer's WebGL2 context.
 * @param {{ getContext(): WebGL2RenderingContext | WebGLRenderingContext }} renderer a THREE.WebGLRenderer
 * @param {string} fragmentSource
 * @returns {{ ok: boolean, errors: CompileError[] }}
 */
export function compileCustom(renderer, fragmentSource) {
  const gl = renderer.getContext();
  if (gl.isContextLost()) return { ok: false, errors: [{ line: 0, message: 'the WebGL context is lost' }] };
  const shader = gl.createShader(gl.FRAGMENT_SHADER);
  if (!shader) return { ok: false, errors: [{ line: 0, message: 'WebGL could not make a shader' }] };
  gl.shaderSource(shader, PREFIX + fragmentSource);
  gl.compileShader(shader);
  const ok = Boolean(gl.getShaderParameter(shader, gl.COMPILE_STATUS));
  const log = ok ? '' : (gl.getShaderInfoLog(shader) ?? '');
  gl.deleteShader(shader);
  if (ok) return { ok, errors: [] };
  const errors = logErrors(log);
  return { ok, errors: errors.length ? errors : [{ line: 0, message: 'the shader does not compile (no log)' }] };
}
