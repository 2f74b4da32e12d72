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

const probe = { quad: null, camera: null, target: null };

/**
 * Compiles `material` on `renderer` the way a draw would (renderer.compile: the same program three.js then draws
 * with, so nothing is compiled twice), into a render target when `offscreen` (a target's colour space is part of
 * the program), and checks that it links. A failure is heard through three.js's own hook
 * (renderer.debug.onShaderError, in place of its console error): returns the logs then, else null.
 * @param {THREE.WebGLRenderer} renderer
 * @param {THREE.ShaderMaterial} material
 * @param {{ offscreen?: boolean }} [options]
 * @returns {{ vertex: string, fragment: string, program: string } | null}
 */
export function compileShader(renderer, material, { offscreen = false } = {}) {
  probe.quad ??= Object.assign(new THREE.Mesh(new THREE.PlaneGeometry(2, 2)), { frustumCulled: false });
  probe.camera ??= new THREE.Camera();
  probe.target ??= new THREE.WebGLRenderTarget(1, 1);
  /** @type {{ vertex: string, fragment: string, program: string } | null} */
  let failed = null;
  const { debug } = renderer;
  const [hook, previous] = [debug.onShaderError, renderer.getRenderTarget()];
  debug.onShaderError = (gl, program, vertex, fragment) => {
    const log = (/** @type {string | null} */ text) => text ?? '';
    failed = {
      vertex: log(gl.getShaderInfoLog(vertex)),
      fragment: log(gl.getShaderInfoLog(fragment)),
      program: log(gl.getProgramInfoLog(program)),
    };
  };
  try {
    probe.quad.material = material;
    renderer.setRenderTarget(offscreen ? probe.target : null);
    renderer.compile(probe.quad, probe.camera);
    renderer.properties.get(material).currentProgram?.getUniforms(); // three.js's link check: the hook on failure
  } finally {
    debug.onShaderError = hook;
    renderer.setRenderTarget(previous);
    probe.quad.material = null;
  }
  return failed;
}
