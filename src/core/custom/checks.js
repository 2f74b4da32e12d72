// @ts-check
// The live checks of a user-written term, on the GPU: the code is evaluated once at every input of its slot's
// check plan (the parity grid with its stress inputs, the quadrature nodes, the swapped pairs, the curve) and the
// values reduced in JS against the float64 reference of the catalogue (check-inputs.js, check-report.js).
import { checkPlan } from './check-inputs.js';
import { checkReport } from './check-report.js';
import { evaluateCustom } from './gpu-eval.js';

/** @typedef {ReturnType<typeof checkReport>} CheckReport */

/**
 * The checks of `code` in a slot, or its errors (static checks or compile, on the user's lines).
 * @param {{ getContext(): WebGL2RenderingContext | WebGLRenderingContext }} renderer a THREE.WebGLRenderer
 * @param {string} slotKey
 * @param {string} code
 * @param {Record<string, number>} params slider values by name (a missing one: the slider's default)
 * @param {{ reference?: string }} [options] the catalogue term to compare with (default: the slot's)
 * @returns {CheckReport | { errors: { line: number, message: string }[] }}
 */
export function runChecks(renderer, slotKey, code, params, { reference } = {}) {
  const plan = checkPlan(slotKey);
  const values = evaluateCustom(renderer, slotKey, code, params, plan.inputs);
  if (!(values instanceof Float32Array)) return values;
  return checkReport(plan, values, reference);
}
