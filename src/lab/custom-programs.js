// The lab's programs when its BRDF is the user's whole BRDF: the lab's program with the user's chunk and
// lab-custom-brdf.glsl in place of measured.glsl (lab-material.glsl's path for a whole BRDF), and the user's slider
// uniforms beside the lab's. Programs of older code (or of other slider names) are let go when it changes.
import { assembleGlsl } from '../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../core/gpu/shader-chunks.js';
import { definesKey } from '../core/gpu/program-cache.js';
import { withCustomChunk } from '../core/custom/assemble.js';
import { fullscreenMaterial } from './fullscreen-material.js';

const FRAGMENT = 'lab-shade.frag.glsl';

/** The shader chunks of the lab's program with `code` (a customBRDF) as its whole BRDF. */
const customBrdfChunks = (code) => ({
  ...withCustomChunk(SHADER_CHUNKS, 'brdf', code),
  'measured.glsl': SHADER_CHUNKS['lab-custom-brdf.glsl'],
});

/** The fragment source of the lab's program of `defines` with `code` as its BRDF (compileCustom checks it). */
export const customBrdfFragment = (defines, code) =>
  assembleGlsl(SHADER_CHUNKS[FRAGMENT], { defines, chunks: customBrdfChunks(code) });

/** `get(defines, { code, params })`: the program, its sliders set to `params`; `has`, `dispose` as a cache's. */
export function createCustomPrograms(uniforms) {
  let code = null;
  let names = '';
  let sliders = {};
  const programs = new Map();
  const clear = () => {
    programs.forEach((p) => p.dispose());
    programs.clear();
  };
  return {
    get(defines, custom) {
      const nextNames = Object.keys(custom.params).sort().join();
      if (custom.code !== code || nextNames !== names) {
        clear(); // a program's uniforms are fixed when it is made
        [code, names, sliders] = [custom.code, nextNames, {}];
      }
      for (const [name, value] of Object.entries(custom.params)) (sliders[name] ??= { value }).value = value;
      const key = definesKey(defines);
      if (!programs.has(key)) {
        const chunks = customBrdfChunks(code);
        programs.set(key, fullscreenMaterial(FRAGMENT, { uniforms: { ...uniforms, ...sliders }, defines, chunks }));
      }
      return programs.get(key);
    },
    has: (defines, custom) =>
      custom.code === code && Object.keys(custom.params).sort().join() === names && programs.has(definesKey(defines)),
    get size() {
      return programs.size;
    },
    dispose: clear,
  };
}
