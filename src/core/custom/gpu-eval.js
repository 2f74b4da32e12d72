// @ts-check
// Evaluates a user-written term on the GPU, one texel per input, with the parity harness's evaluation
// (src/core/gpu/parity.js): the same float32 render target, the same read-back. The code passes the static checks
// (parse.js: no unbounded loop reaches the GPU) and three.js's compile (compile.js: no console output, and the
// program compiled there is the one the evaluation draws with) first.
import { evaluateOnGpu, parityFragment } from '../gpu/parity.js';
import { SHADER_CHUNKS } from '../gpu/shader-chunks.js';
import { customChunkName, withCustomChunk } from './assemble.js';
import { compileCustom } from './compile.js';
import { parseCustom } from './parse.js';
import { slotOf } from './slots.js';

/**
 * The parity case of a slot's code over `inputs`: its chunk, its call over a and b, its slider uniforms (a value
 * of `params`, else the slider's default).
 * @param {string} slotKey
 * @param {string} code
 * @param {import('./parse.js').Param[]} sliders
 * @param {Record<string, number>} params
 * @param {number[][]} inputs
 */
function customCase(slotKey, code, sliders, params, inputs) {
  const slot = slotOf(slotKey);
  const uniforms = Object.fromEntries(
    sliders.map((s) => [s.name, Number.isFinite(params?.[s.name]) ? params[s.name] : s.value]),
  );
  return {
    name: slot.fn,
    chunk: customChunkName(slotKey),
    chunks: withCustomChunk(SHADER_CHUNKS, slotKey, code),
    glsl: slot.evalCall,
    outputs: slot.outputs,
    uniforms,
    args: inputs,
  };
}

/**
 * The slot's values at `inputs` (each in the order of SLOTS[slotKey].inputs): 4 floats per input, the return in
 * .x or .xyz; or the errors (the user's lines) when the code fails the static checks or does not compile.
 * @param {{ getContext(): WebGL2RenderingContext | WebGLRenderingContext }} renderer a THREE.WebGLRenderer
 * @param {string} slotKey
 * @param {string} code
 * @param {Record<string, number>} params slider values by name
 * @param {number[][]} inputs
 * @returns {Float32Array | { errors: { line: number, message: string }[] }}
 */
export function evaluateCustom(renderer, slotKey, code, params, inputs) {
  const slot = slotOf(slotKey);
  const bad = inputs.findIndex((x) => !Array.isArray(x) || x.length !== slot.inputs.length);
  if (bad >= 0) throw new Error(`custom: input ${bad} of ${slot.fn} must be ${slot.inputs.length} numbers`);
  const parsed = parseCustom(slotKey, code);
  if (!parsed.ok) return { errors: parsed.problems };
  const testCase = customCase(slotKey, code, parsed.params, params, inputs);
  const compiled = compileCustom(renderer, parityFragment(testCase), { offscreen: true });
  if (!compiled.ok) return { errors: compiled.errors };
  try {
    return evaluateOnGpu(renderer, testCase);
  } finally {
    compiled.release(); // after the evaluation's material took the compiled program over
  }
}
