// The parity harness: evaluates each GLSL function of shaders/ over a grid of inputs on the GPU (one texel
// per input, float32 render target), reads the results back and compares them with the JS reference.
// The JS side is evaluated at the float32-rounded inputs, so only the function's own error is measured.
import * as THREE from 'three';
import { assembleGlsl } from './glsl.js';
import { SHADER_CHUNKS } from './shader-chunks.js';
import { floatTarget } from './gpu-sum.js';
import { createFullscreenPass } from './fullscreen-pass.js';
import { buildShader } from './shader-builder.js';
import { TOLERANCE } from './parity-cases.js';

const WIDTH = 256;

/** An RGBA float table ({ size, data } square, or { width, height, data }) as a texture read with texelFetch. */
function tableTexture({ size, width = size, height = size, data }) {
  const t = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  t.needsUpdate = true;
  return t;
}

/** Floats per input of a case: its longest tuple, in whole texels, at least two (a and b). */
const texelsOf = (testCase) => Math.max(2, Math.ceil(Math.max(0, ...testCase.args.map((a) => a.length)) / 4));

/** Rows of one texel layer: one texel per input, WIDTH to a row. */
const rowsOf = (testCase) => Math.max(1, Math.ceil(testCase.args.length / WIDTH));

/**
 * The fragment shader that evaluates a case's expression once per texel: its chunk, its prelude (helpers the
 * expression calls), then parity.frag.glsl with CALL, the expression padded to a vec4, and ARG_ROWS, the rows of
 * one texel layer of the inputs. `testCase.chunks` (name → text) stands in for the shader chunks: a user-written
 * term brings its own (src/core/custom/assemble.js).
 */
export function parityFragment(testCase) {
  const wrap = `vec4(${testCase.glsl}${', 0.0'.repeat(4 - testCase.outputs)})`; // pad to vec4
  const prelude = testCase.prelude ? `${testCase.prelude}\n` : '';
  return assembleGlsl(`#include "${testCase.chunk}"\n${prelude}${SHADER_CHUNKS['parity.frag.glsl']}`, {
    defines: { ...testCase.defines, CALL: wrap, ARG_ROWS: rowsOf(testCase) },
    chunks: testCase.chunks ?? SHADER_CHUNKS,
  });
}

/**
 * The inputs as one float texture: layer k (rows k·rows … (k + 1)·rows - 1) holds floats 4k … 4k + 3 of every
 * tuple, one texel per tuple.
 */
function inputTexture(testCase) {
  const rows = rowsOf(testCase);
  const layers = texelsOf(testCase);
  const data = new Float32Array(WIDTH * rows * layers * 4);
  testCase.args.forEach((args, i) =>
    args.forEach((x, j) => (data[(Math.floor(j / 4) * rows * WIDTH + i) * 4 + (j % 4)] = x)),
  );
  const t = new THREE.DataTexture(data, WIDTH, rows * layers, THREE.RGBAFormat, THREE.FloatType);
  t.needsUpdate = true;
  return t;
}

/**
 * Evaluates a case on the GPU: one texel per tuple of `testCase.args` (any number of floats: a.xyzw, b.xyzw,
 * arg(i)), read back as 4 floats per tuple. `testCase.uniforms` (name → number) are further uniforms its code reads.
 */
export function evaluateOnGpu(renderer, testCase) {
  const n = testCase.args.length;
  const height = rowsOf(testCase);
  const input = inputTexture(testCase);
  const tables = Object.entries(testCase.tables ?? {}).map(([name, table]) => [name, tableTexture(table())]);
  const extra = Object.entries(testCase.uniforms ?? {}).map(([name, value]) => [name, { value }]);
  const material = buildShader('parity.frag.glsl', {
    source: parityFragment(testCase),
    uniforms: {
      ...Object.fromEntries(extra),
      uArgs: { value: input },
      ...Object.fromEntries(tables.map(([name, t]) => [name, { value: t }])),
    },
  });
  const target = floatTarget(WIDTH, height);
  const pass = createFullscreenPass();
  pass.render(renderer, material, target);
  const out = new Float32Array(WIDTH * height * 4);
  renderer.readRenderTargetPixels(target, 0, 0, WIDTH, height, out);
  [pass, input, ...tables.map(([, t]) => t), material, target].forEach((x) => x.dispose());
  return out.subarray(0, n * 4);
}

/** Compares one case; returns its summary row. */
export function compareCase(testCase, gpu) {
  const { atol, rtol } = testCase.tolerance ?? TOLERANCE;
  let maxAbs = 0;
  let maxRel = 0;
  let worst = null;
  let failures = 0;
  let invalid = 0;
  testCase.args.forEach((args, i) => {
    const f32 = args.map(Math.fround);
    const want = [].concat(testCase.js(...f32));
    want.forEach((j, o) => {
      const g = gpu[i * 4 + o];
      if (!Number.isFinite(g) || g < testCase.range[0] || g > testCase.range[1] * (1 + 1e-6)) invalid++;
      const abs = Math.abs(g - j);
      const rel = abs / Math.max(Math.abs(j), 1e-30);
      if (!(abs <= atol + rtol * Math.abs(j))) failures++;
      if (!(abs <= maxAbs) || !worst) {
        maxAbs = Number.isFinite(abs) ? Math.max(abs, maxAbs) : Infinity;
        worst = { args: f32, output: o, gpu: g, js: j };
      }
      if (Math.abs(j) > 1e-6) maxRel = Math.max(maxRel, rel);
    });
  });
  return {
    name: testCase.name,
    count: testCase.args.length,
    maxAbs,
    maxRel,
    worst,
    failures,
    invalid,
    tolerance: { atol, rtol },
    pass: failures === 0 && invalid === 0,
  };
}

export function runParity(renderer, cases) {
  return cases.map((c) => compareCase(c, evaluateOnGpu(renderer, c)));
}
