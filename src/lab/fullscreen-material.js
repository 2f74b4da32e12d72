// A material for one of the lab's full-screen passes (drawn with createFullscreenPass): the fragment program
// `fragment` of shaders/, assembled with `defines`, over the full-screen vertex program.
import * as THREE from 'three';
import { assembleGlsl } from '../core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../core/gpu/shader-chunks.js';

export const fullscreenMaterial = (fragment, { uniforms, defines = {} }) =>
  new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms,
    vertexShader: SHADER_CHUNKS['fullscreen.vert.glsl'],
    fragmentShader: assembleGlsl(SHADER_CHUNKS[fragment], { defines }),
    depthTest: false,
    depthWrite: false,
  });
