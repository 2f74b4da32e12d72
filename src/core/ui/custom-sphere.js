// A user-written term on a sphere of the sphere grid: the code that ran (custom-area.js) compiled in the sphere's
// own program first (compile-guard.js: a name of the user's may clash with one of brdf.glsl's; the last code that
// compiled there keeps drawing), given to the grid as the cell's own chunks, its sliders as uniforms.
import { withCustomChunk } from '../custom/assemble.js';
import { createCompileGuard } from '../custom/compile-guard.js';
import { SHADER_CHUNKS } from '../gpu/shader-chunks.js';
import { sphereFragment } from './sphere-grid.js';

/** @param {() => any} getRenderer  the sphere grid's renderer */
export function createCustomSphere(getRenderer) {
  const guard = createCompileGuard(getRenderer, { vertex: 'sphere-impostor.vert.glsl' });
  return {
    /**
     * What a cell of `defines` needs to draw `slotKey`'s code for `state`: { own, uniforms } (sphere-grid.js), or
     * null while no code has run; the problems of a code that does not compile in the sphere go to the panel.
     * @param {ReturnType<typeof import('./custom-area.js').createCustomArea>} area
     * @param {string} slotKey
     * @param {any} state
     * @param {Record<string, unknown>} defines
     */
    cell(area, slotKey, state, defines) {
      const ran = area.ran(slotKey);
      if (!ran || !getRenderer()) return null;
      const chunksOf = (/** @type {string} */ code) => withCustomChunk(SHADER_CHUNKS, slotKey, code);
      const { code, problems } = guard.pick(ran, (c) => [sphereFragment(defines, chunksOf(c))]);
      area.report(slotKey, problems);
      if (!code) return null;
      const uniforms = area.sliderValues(slotKey, code, state.params) ?? {};
      // a program's uniforms are fixed when it is made: its key names the sliders too
      return { own: { key: `${code}\u0000${Object.keys(uniforms)}`, chunks: chunksOf(code) }, uniforms };
    },
  };
}
