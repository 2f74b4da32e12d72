// Grades shader exercises on this browser's GPU: one WebGL2 renderer for the page, made at the first Check, with
// custom-core's static check (parseCustom) and evaluation (evaluateCustom) handed to the pure grader.
import * as THREE from 'three';
import { parseCustom } from '../core/custom/parse.js';
import { evaluateCustom } from '../core/custom/gpu-eval.js';
import { gradeShader } from './shader-grader.js';

let renderer = null;

/** The page's renderer, or null without WebGL2 and float render targets. */
function rendererOnce() {
  if (renderer) return renderer;
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2');
  if (!gl || !gl.getExtension('EXT_color_buffer_float')) return null;
  renderer = new THREE.WebGLRenderer({ canvas, context: gl });
  return renderer;
}

/** Not a grade of the student's code (the browser or the grader failed): not counted as an attempt. */
const failure = (summary) => ({ passed: false, score: 0, counted: false, summary, details: [] });

/** gradeShader's result for `code`; a browser without the GPU features gets a message, not a grade. */
export async function gradeOnGpu(exercise, code) {
  const r = rendererOnce();
  if (!r) return failure('Grading needs WebGL2 with float render targets, which this browser did not provide.');
  const evaluate = (slot, text, inputs) => evaluateCustom(r, slot, text, {}, inputs);
  try {
    return gradeShader(exercise, code, { parse: parseCustom, evaluate });
  } catch (e) {
    return failure(`The grader could not run your code (${e.message}).`);
  }
}
