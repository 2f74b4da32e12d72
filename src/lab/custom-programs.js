// The lab's programs when its BRDF is the user's whole BRDF: the lab's program with the user's chunk and
// lab-custom-brdf.glsl in place of measured.glsl (lab-material.glsl's path for a whole BRDF), and the user's slider
// uniforms beside the lab's. Programs of older code (or of other slider names) are let go when it changes. The same
// for the user's anisotropic D and V (customDAniso, customVAniso): their chunks beside the lab's own.
import { SHADER_CHUNKS } from '../core/gpu/shader-chunks.js';
import { fragmentSource } from '../core/gpu/shader-builder.js';
import { createProgramCache } from '../core/gpu/program-cache.js';
import { withCustomChunk } from '../core/custom/assemble.js';
import { fullscreenMaterial } from './fullscreen-material.js';

const FRAGMENT = 'lab-shade.frag.glsl';

/** The shader chunks of the lab's program with `code` (a customBRDF) as its whole BRDF. */
const customBrdfChunks = (code) => ({
  ...withCustomChunk(SHADER_CHUNKS, 'brdf', code),
  'measured.glsl': SHADER_CHUNKS['lab-custom-brdf.glsl'],
});

/** The fragment source of the lab's program of `defines` with `code` as its BRDF (compile-guard.js checks it). */
export const customBrdfFragment = (defines, code) =>
  fragmentSource(FRAGMENT, { defines, chunks: customBrdfChunks(code) });

/** The shader chunks with the user's terms `codes` ({ DAniso?, VAniso? }: code by slot) added. */
export const customTermChunks = (codes) =>
  Object.entries(codes).reduce((chunks, [slot, code]) => withCustomChunk(chunks, slot, code), SHADER_CHUNKS);

/** The fragment source of the lab's program of `defines` with the user's terms `codes` (customTermChunks). */
export const customTermsFragment = (defines, codes) =>
  fragmentSource(FRAGMENT, { defines, chunks: customTermChunks(codes) });

/**
 * `get(defines, { code, params })`: the program, its sliders set to `params`; `has`, `dispose` as a cache's.
 * `chunksOf(code)` gives the program's chunks: the user's whole BRDF by default, or customTermChunks (code by slot).
 */
export function createCustomPrograms(uniforms, chunksOf = customBrdfChunks) {
  let current = null; // the key of the code (and slider names) the programs are made with
  let sliders = {};
  const programs = createProgramCache((defines, own) =>
    fullscreenMaterial(FRAGMENT, {
      uniforms: { ...uniforms, ...sliders },
      defines,
      chunks: chunksOf(own.code),
    }),
  );
  const ownOf = (custom) => ({
    key: `${JSON.stringify(custom.code)}\u0000${Object.keys(custom.params).sort().join()}`,
    code: custom.code,
  });
  return {
    get(defines, custom) {
      const own = ownOf(custom);
      if (own.key !== current) {
        programs.keepOnly(() => false); // a program's uniforms are fixed when it is made
        [current, sliders] = [own.key, {}];
      }
      for (const [name, value] of Object.entries(custom.params)) (sliders[name] ??= { value }).value = value;
      return programs.get(defines, own);
    },
    has: (defines, custom) => programs.has(defines, ownOf(custom)),
    get size() {
      return programs.size;
    },
    dispose: () => programs.dispose(),
  };
}
