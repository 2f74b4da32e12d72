// A material for one of the lab's full-screen passes (drawn with createFullscreenPass): the fragment program
// `fragment` of shaders/, assembled with `defines` (and `chunks`, when a program holds chunks of its own: a user's
// BRDF), over the full-screen vertex program.
import * as THREE from 'three';
import { assembleGlsl } from '../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../core/gpu/shader-chunks.js';

export const fullscreenMaterial = (fragment, { uniforms, defines = {}, chunks = SHADER_CHUNKS }) =>
  new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms,
    vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
    fragmentShader: assembleGlsl(chunks[fragment], { defines, chunks }),
    depthTest: false,
    depthWrite: false,
  });
