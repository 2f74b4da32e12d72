// The page of tests/browser/custom-terms.test.js: a three.js renderer and the core of user-written terms
// (src/core/custom), handed to the test as window.__customTerms, with a panel's use of watchContext: each program
// is tried, kept when it drew, and the kept one checked again when a lost context comes back.
import * as THREE from 'three';
import { SLOTS } from '../../src/core/custom/slots.js';
import { compileCustom } from '../../src/core/custom/compile.js';
import { evaluateCustom } from '../../src/core/custom/gpu-eval.js';
import { runChecks } from '../../src/core/custom/checks.js';
import { watchContext } from '../../src/core/custom/context-watch.js';

const renderer = new THREE.WebGLRenderer({ canvas: document.getElementById('gl') });
const check = (slot, code, params = {}, options = {}) => runChecks(renderer, slot, code, params, options);
const loseContext = renderer.getContext().getExtension('WEBGL_lose_context');
// every fragment shader the context compiles, counted (three.js's and any other), for the compile-once test
const gl = renderer.getContext();
const compileShader = gl.compileShader.bind(gl);
let fragmentCompiles = 0;
gl.compileShader = (shader) => {
  if (gl.getShaderParameter(shader, gl.SHADER_TYPE) === gl.FRAGMENT_SHADER) fragmentCompiles++;
  compileShader(shader);
};
const events = [];
const watch = watchContext(renderer, {
  onLost: (message, suspect) => events.push({ type: 'lost', message, suspect }),
  onRestored: (program) =>
    events.push({ type: 'restored', program, report: program && check(program.slot, program.code, program.params) }),
});

window.__customTerms = {
  SLOTS,
  renderer,
  compileCustom: (source) => {
    const { ok, errors, release } = compileCustom(renderer, source, { vertex: 'sphere-impostor.vert.glsl' });
    release();
    return { ok, errors };
  },
  evaluate: (slot, code, params, inputs) => {
    const out = evaluateCustom(renderer, slot, code, params, inputs);
    return out instanceof Float32Array ? Array.from(out) : out;
  },
  check,
  /** Runs a program as a panel would: tried, then kept once it drew; `draw: false` stops before it draws. */
  run(program, { draw = true } = {}) {
    watch.trying(program);
    if (!draw) return null;
    const report = check(program.slot, program.code, program.params);
    if (!('errors' in report)) watch.drew();
    return report;
  },
  events,
  fragmentCompiles: () => fragmentCompiles,
  lose: () => loseContext.loseContext(),
  restore: () => loseContext.restoreContext(),
};
