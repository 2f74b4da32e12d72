// The GPU half of `npm run bench`: each variant's GLSL expression evaluated LOOPS times per pixel over a
// full-screen pass; each frame is drained (a 1-pixel readPixels waits for the GPU), the median frame kept.
import { FAMILIES } from './families.js';
import { assembleGlsl } from '../src/core/gpu/glsl.js';
import { compareWithMeshStandard } from './versus-three.js';

const params = new URLSearchParams(location.search);
const FRAMES = Number(params.get('frames') ?? 9);
const SIZE = 256;
const LOOPS = 16;

const canvas = document.createElement('canvas');
canvas.width = canvas.height = SIZE;
const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false });

const VERT = `#version 300 es
in vec2 position;
void main() { gl_Position = vec4(position, 0.0, 1.0); }`;

function fragment(expr, setup = {}) {
  const body = `#include "fresnel.glsl"
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
  return (
    `#version 300 es\nprecision highp float;\nprecision highp ` +
    `int;\n${assembleGlsl(body, { defines: setup.defines ?? {} })}`
  );
}

function program(expr, setup) {
  const p = gl.createProgram();
  for (const [type, src] of [
    [gl.VERTEX_SHADER, VERT],
    [gl.FRAGMENT_SHADER, fragment(expr, setup)],
  ]) {
    const s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(`${expr}: ${gl.getShaderInfoLog(s)}`);
    gl.attachShader(p, s);
  }
  gl.bindAttribLocation(p, 0, 'position');
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
  return p;
}

const buffer = gl.createBuffer();
gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
gl.enableVertexAttribArray(0);
gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
const pixel = new Uint8Array(4);

function timeFrames(p) {
  gl.useProgram(p);
  const times = [];
  for (let i = 0; i < FRAMES + 2; i++) {
    const t0 = performance.now();
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel); // waits for the frame
    if (i >= 2) times.push(performance.now() - t0); // the first two warm up (compilation, caches)
  }
  times.sort((a, b) => a - b);
  return times[Math.floor(times.length / 2)];
}

/** Binds a family's square RGBA float tables ({ size, data }) to its program's samplers, units 0, 1, … */
function bindTables(p, tables = {}) {
  gl.useProgram(p);
  Object.entries(tables).forEach(([name, table], unit) => {
    const { size, data } = table();
    const t = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, size, size, 0, gl.RGBA, gl.FLOAT, data);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.uniform1i(gl.getUniformLocation(p, name), unit);
  });
  return p;
}

// a program that does not compile throws: say so at once (bench.js stops waiting) instead of never being done
window.addEventListener('error', () => (window.__gpuBenchFailed = true));
const debug = gl.getExtension('WEBGL_debug_renderer_info');
const only = params.get('family'); // one family alone (npm run bench -- --family KEY)
const results = {};
for (const family of FAMILIES.filter((f) => !only || f.key === only)) {
  results[family.key] = {};
  for (const v of family.variants.filter((w) => w.glsl))
    results[family.key][v.key] = timeFrames(bindTables(program(v.glsl, family.gpu), family.gpu?.tables));
}
window.__gpuBench = {
  done: true,
  versusThree: only ? null : compareWithMeshStandard({ frames: FRAMES }),
  baselineMs: timeFrames(program('x * y')), // the loop and the pass alone: part of every frame above
  renderer: debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
  setup: { size: SIZE, loops: LOOPS, frames: FRAMES },
  results,
};
document.getElementById('status').textContent = 'Done.';
