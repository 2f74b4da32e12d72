// The GPU half of `npm run bench`: each variant's GLSL expression evaluated LOOPS times per pixel over a
// full-screen pass; each frame is drained (a 1-pixel readPixels waits for the GPU), the median frame kept.
// Each program goes through the app's one shader builder (src/core/gpu/shader-builder.js) and is checked by its
// compileShader, as every view's is.
import * as THREE from 'three';
import { FAMILIES } from './families.js';
import { SHADER_CHUNKS } from '../src/core/gpu/shader-chunks.js';
import { buildShader, compileShader } from '../src/core/gpu/shader-builder.js';
import { compareWithMeshStandard } from './versus-three.js';

const params = new URLSearchParams(location.search);
const FRAMES = Number(params.get('frames') ?? 9);
// --quick (the bench's test) asks for a small pass: only the report's shape is read, and software WebGL's cost
// grows with the pixels
const SIZE = Number(params.get('size') ?? 256);
const SPHERE_SIZE = Number(params.get('sphereSize') ?? 512);
const LOOPS = 16;

const canvas = document.createElement('canvas');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: false });
renderer.setPixelRatio(1);
renderer.setSize(SIZE, SIZE, false);
const gl = renderer.getContext();
const pass = Object.assign(new THREE.Mesh(new THREE.PlaneGeometry(2, 2)), { frustumCulled: false });
const scene = new THREE.Scene().add(pass);
const camera = new THREE.Camera();

/** The bench's fragment program: `expr` evaluated LOOPS times per pixel, after the term chunks it calls. */
function fragment(expr, setup = {}) {
  return `#include "fresnel.glsl"
#include "visibility.glsl"
#include "diffuse.glsl"
${setup.chunk ? `#include "${setup.chunk}"` : ''}
out vec4 fragColor;
void main() {
  vec2 p = gl_FragCoord.xy / ${SIZE.toFixed(1)};
  float acc = 0.0;
  for (int k = 0; k < ${LOOPS}; k++) {
    // inputs vary per pixel and per iteration so nothing can be hoisted out of the loop
    float x = fract(p.x + float(k) * 0.6180339887);
    float y = fract(p.y + float(k) * 0.7548776662);
    acc += ${expr};
  }
  fragColor = vec4(acc);
}`;
}

/** A family's RGBA float tables ({ size, data } square, or { width, height, data }) as sampler uniforms. */
function tableUniforms(tables = {}) {
  return Object.fromEntries(
    Object.entries(tables).map(([name, table]) => {
      const { size, width = size, height = size, data } = table();
      const texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
      texture.minFilter = texture.magFilter = THREE.NearestFilter;
      texture.needsUpdate = true;
      return [name, { value: texture }];
    }),
  );
}

/** The program of `expr` with a family's setup (its chunk, defines and tables), compiled; throws if it fails. */
function program(expr, setup = {}) {
  const chunks = { ...SHADER_CHUNKS, 'gpu-bench.frag.glsl': fragment(expr, setup) };
  const uniforms = tableUniforms(setup.tables);
  const material = buildShader('gpu-bench.frag.glsl', { chunks, defines: setup.defines ?? {}, uniforms });
  const failed = compileShader(renderer, material);
  if (failed) throw new Error(`${expr}: ${failed.fragment || failed.vertex || failed.program}`);
  return material;
}

const pixel = new Uint8Array(4);

function timeFrames(material) {
  pass.material = material;
  const times = [];
  for (let i = 0; i < FRAMES + 2; i++) {
    const t0 = performance.now();
    renderer.render(scene, camera);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel); // waits for the frame
    if (i >= 2) times.push(performance.now() - t0); // the first two warm up (compilation, caches)
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(times.length / 2)];
}

// a program that does not compile throws: say so at once (bench.js stops waiting) instead of never being done
window.addEventListener('error', () => (window.__gpuBenchFailed = true));
const debug = gl.getExtension('WEBGL_debug_renderer_info');
const only = params.get('family'); // one family alone (npm run bench -- --family KEY)
const results = {};
for (const family of FAMILIES.filter((f) => !only || f.key === only)) {
  results[family.key] = {};
  for (const v of family.variants.filter((w) => w.glsl))
    // a variant's own defines (OpenPBR's layers compiled out) beside the family's
    results[family.key][v.key] = timeFrames(
      program(v.glsl, { ...family.gpu, defines: { ...family.gpu?.defines, ...v.defines } }),
    );
}
window.__gpuBench = {
  done: true,
  versusThree: only ? null : compareWithMeshStandard({ size: SPHERE_SIZE, frames: FRAMES }),
  baselineMs: timeFrames(program('x * y')), // the loop and the pass alone: part of every frame above
  renderer: debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
  setup: { size: SIZE, loops: LOOPS, frames: FRAMES },
  results,
};
document.getElementById('status').textContent = 'Done.';
