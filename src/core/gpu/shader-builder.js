// The one way the app makes a three.js program: a fragment program of shaders/ (or of `chunks`, when a program
// holds chunks of its own: a user's term), assembled with its #define switches (glsl.js: a switch is 1, a value a
// number), over one of the vertex programs of shaders/, as a GLSL3 ShaderMaterial. Views keep what they build in
// a program cache (program-cache.js), so a program is built once per key.
import * as THREE from 'three';
import { assembleGlsl } from './glsl.js';
import { SHADER_CHUNKS } from './shader-chunks.js';

/** Programs built so far, by fragment file name. */
const built = new Map();

/**
 * The source of the fragment program `fragment` (a file name of shaders/ or of `chunks`) for `defines`.
 * @param {string} fragment
 * @param {{ defines?: Record<string, number>, chunks?: Record<string, string> }} [options]
 */
export const fragmentSource = (fragment, { defines = {}, chunks = SHADER_CHUNKS } = {}) => {
  if (!(fragment in chunks)) throw new Error(`shader: no program "${fragment}"`);
  return assembleGlsl(chunks[fragment], { defines, chunks });
};

/**
 * A ShaderMaterial of `fragment` with `defines`, over the vertex program `vertex` (a file name of shaders/);
 * `uniforms` are the material's own (shared when the caller passes the same object), `source` the fragment's
 * text when the caller assembled it (the parity harness's, around a case's call), `options` more ShaderMaterial
 * fields (depthTest, …).
 * @param {string} fragment
 * @param {{ uniforms?: Record<string, { value: unknown }>, defines?: Record<string, number>,
 *   chunks?: Record<string, string>, vertex?: string, source?: string, [option: string]: unknown }} [spec]
 */
export function buildShader(
  fragment,
  { uniforms = {}, defines = {}, chunks = SHADER_CHUNKS, vertex = 'fullscreen.vert.glsl', source, ...options } = {},
) {
  const material = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms,
    vertexShader: SHADER_CHUNKS[vertex],
    fragmentShader: source ?? fragmentSource(fragment, { defines, chunks }),
    ...options,
  });
  built.set(fragment, (built.get(fragment) ?? 0) + 1);
  return material;
}

/** How many programs of each fragment file have been built so far (what a test reads: one per key). */
export const shadersBuilt = () => Object.fromEntries(built);
