// The page of tests/browser/custom-terms.test.js: a three.js renderer and the core of user-written terms
// (src/core/custom), handed to the test as window.__customTerms.
import * as THREE from 'three';
import { SLOTS } from '../../src/core/custom/slots.js';
import { compileCustom } from '../../src/core/custom/compile.js';
import { evaluateCustom } from '../../src/core/custom/gpu-eval.js';
import { runChecks } from '../../src/core/custom/checks.js';

const renderer = new THREE.WebGLRenderer({ canvas: document.getElementById('gl') });

window.__customTerms = {
  SLOTS,
  renderer,
  compileCustom: (source) => compileCustom(renderer, source),
  evaluate: (slot, code, params, inputs) => {
    const out = evaluateCustom(renderer, slot, code, params, inputs);
    return out instanceof Float32Array ? Array.from(out) : out;
  },
  check: (slot, code, params = {}, options = {}) => runChecks(renderer, slot, code, params, options),
};
