// A material for one of the lab's full-screen passes (drawn with createFullscreenPass): the fragment program
// `fragment` of shaders/, built with `defines` (and `chunks`, when a program holds chunks of its own: a user's
// BRDF) over the full-screen vertex program, by the app's one shader builder; no depth.
import { buildShader } from '../core/gpu/shader-builder.js';

export const fullscreenMaterial = (fragment, { uniforms, defines = {}, chunks }) =>
  buildShader(fragment, { uniforms, defines, chunks, depthTest: false, depthWrite: false });
