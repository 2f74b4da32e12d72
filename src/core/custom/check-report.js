// @ts-check
// From the GPU's values at a check plan's inputs (check-inputs.js) to the live checks' report: NaN/Inf/negative
// values with the first offending input, D's normalisation, G = V (n·l)(n·v) within [0, 1], reciprocity, the
// white furnace, the largest difference from a catalogue term (float64, references.js) and the curves to plot.
// Pure: the browser half (checks.js) only evaluates.
import { TOLERANCE } from '../gpu/parity-cases.js';
import { referenceFunction, referenceOptions } from './references.js';
import { slotOf } from './slots.js';
import { WEAK_FURNACE_VIEWS_DEG } from './check-inputs.js';
import { smithG1BeckmannAniso, smithG1GGXAniso } from '../../math/anisotropic.js';

/** G may pass 1 by float32's rounding of a correct V, not more. */
export const G_ALLOWANCE = 1e-5;
/** f(l, v) and f(v, l) may differ by float32's rounding of a reciprocal BRDF, not more. */
export const RECIPROCITY_TOLERANCE = 1e-5;

/** @typedef {{ inputs: Record<string, number>, value: number, text: string }} Offender */

/**
 * An input as a record of the slot's input names.
 * @param {import('./slots.js').Slot} slot @param {number[]} input
 * @returns {Record<string, number>}
 */
const named = (slot, input) => Object.fromEntries(slot.inputs.map((name, i) => [name, Math.fround(input[i])]));

/**
 * The outputs of input i.
 * @param {Float32Array} values @param {number} i @param {number} outputs
 */
const outputsAt = (values, i, outputs) => Array.from(values.subarray(i * 4, i * 4 + outputs));

/**
 * NaN, ±Inf and negative values over the stress grid: how many inputs give them, and the first.
 * @param {import('./slots.js').Slot} slot @param {number[][]} inputs @param {Float32Array} values @param {number} at
 */
export function nonFiniteReport(slot, inputs, values, at) {
  let count = 0;
  let negative = 0;
  /** @type {Offender | null} */
  let first = null;
  inputs.forEach((input, i) => {
    const out = outputsAt(values, at + i, slot.outputs);
    const bad = out.find((x) => !Number.isFinite(x) || x < 0);
    if (out.some((x) => !Number.isFinite(x))) count++;
    else if (out.some((x) => x < 0)) negative++;
    if (bad !== undefined && !first) first = { inputs: named(slot, input), value: bad, text: String(bad) };
  });
  return { count, negative, first };
}

/**
 * The largest difference from a reference term over the stress grid; `worst` is where it is largest against the
 * parity harness's tolerance |Δ| ≤ atol + rtol |reference| (a NaN or Inf is the worst of all).
 * @param {import('./slots.js').Slot} slot @param {string} key @param {number[][]} inputs @param {Float32Array} values
 * @param {number} at
 */
export function referenceReport(slot, key, inputs, values, at) {
  const reference = referenceFunction(slot.key, key);
  const { atol, rtol } = TOLERANCE;
  let [maxAbs, maxRel, failures, worstScore] = [0, 0, 0, -1];
  /** @type {(Offender & { output: number, reference: number }) | null} */
  let worst = null;
  inputs.forEach((input, i) => {
    const want = reference(input);
    outputsAt(values, at + i, slot.outputs).forEach((g, o) => {
      const j = want[o];
      const abs = Math.abs(g - j);
      const score = Number.isFinite(abs) ? abs / (atol + rtol * Math.abs(j)) : Infinity;
      if (!(score <= 1)) failures++;
      if (score > worstScore) {
        worstScore = score;
        worst = { inputs: named(slot, input), output: o, value: g, reference: j, text: String(g) };
      }
      maxAbs = Number.isFinite(abs) ? Math.max(maxAbs, abs) : Infinity;
      if (Math.abs(j) > 1e-6) maxRel = Number.isFinite(abs) ? Math.max(maxRel, abs / Math.abs(j)) : Infinity;
    });
  });
  const label = referenceOptions(slot.key)[key];
  return { key, label, maxAbs, maxRel, worst, failures, tolerance: TOLERANCE, pass: failures === 0 };
}

/**
 * ∫ D(m)(n·m) dω at each α of the plan; `worst` is the integral farthest from 1.
 * @param {NonNullable<ReturnType<typeof import('./check-inputs.js').checkPlan>['normalisation']>} parts
 * @param {Float32Array} values
 */
export function normalisationReport(parts, values) {
  const byAlpha = parts.map(({ alpha, weights, start }) => ({
    alpha,
    integral: weights.reduce((sum, w, i) => sum + w * values[(start + i) * 4], 0),
  }));
  const worst = byAlpha.reduce((a, b) => (Math.abs(b.integral - 1) > Math.abs(a.integral - 1) ? b : a)).integral;
  return { worst, byAlpha, alphaMin: parts[0].alpha };
}

/** Smith's G1 of the Λ a reference anisotropic D is paired with (the weak furnace holds only when they agree). */
const G1_OF_REFERENCE = { ggxAniso: smithG1GGXAniso, beckmannAniso: smithG1BeckmannAniso };
export const LAMBDA_LABELS = { ggxAniso: 'GGX’s Λ', beckmannAniso: 'Beckmann’s Λ' };

/**
 * Heitz's (2014) weak white furnace of an anisotropic D with the Λ of the reference `key`: at each view v of
 * WEAK_FURNACE_VIEWS_DEG, G1(v) ∫ D(h) ⟨v·h⟩ dω_h / (n·v), which is 1 for every v when D and Λ agree, over the
 * normalisation's nodes (a node's weight over hz weighs D alone). `worst` is the value farthest from 1.
 * @param {{ alpha: number[], weights: number[], directions: number[][], start: number }[]} parts the anisotropic
 *   D's normalisation parts (check-inputs.js)
 * @param {Float32Array} values @param {string} key
 */
export function weakFurnaceReport(parts, values, key) {
  const g1 = G1_OF_REFERENCE[/** @type {keyof typeof G1_OF_REFERENCE} */ (key)] ?? smithG1GGXAniso;
  const views = WEAK_FURNACE_VIEWS_DEG.map(([t, p]) => [t, p, ...direction(t * DEG, p * DEG)]);
  const byView = parts.flatMap(({ alpha, weights, directions, start }) =>
    views.map(([thetaV, phiV, vx, vy, vz]) => {
      const projected = weights.reduce((sum, w, i) => {
        const [hx, hy, hz] = directions[i];
        return sum + ((w * values[(start + i) * 4]) / hz) * Math.max(vx * hx + vy * hy + vz * hz, 0);
      }, 0);
      return { alpha, thetaV, phiV, value: (g1(vx, vy, vz, alpha[0], alpha[1]) * projected) / vz };
    }),
  );
  const worst = byView.reduce((a, b) => (Math.abs(b.value - 1) > Math.abs(a.value - 1) ? b : a));
  return {
    worst: worst.value,
    at: worst,
    byView,
    lambda: LAMBDA_LABELS[/** @type {keyof typeof LAMBDA_LABELS} */ (key)],
  };
}

const DEG = Math.PI / 180;
/** @param {number} theta @param {number} phi */
const direction = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];

/**
 * G = V (n·l)(n·v) over V's stress grid: its range, and how many values leave [0, 1] (or are not finite).
 * @param {import('./slots.js').Slot} slot @param {number[][]} inputs @param {Float32Array} values @param {number} at
 */
export function gRangeReport(slot, inputs, values, at) {
  let [min, max, outside] = [Infinity, -Infinity, 0];
  /** @type {Offender | null} */
  let first = null;
  inputs.forEach((input, i) => {
    const [nl, nv] = (slot.key === 'VAniso' ? [input[2], input[5]] : input).map(Math.fround); // l.z, v.z
    const g = values[(at + i) * 4] * nl * nv;
    if (Number.isFinite(g)) [min, max] = [Math.min(min, g), Math.max(max, g)];
    if (Number.isFinite(g) && g >= 0 && g <= 1 + G_ALLOWANCE) return;
    outside++;
    first ??= { inputs: named(slot, input), value: g, text: String(g) };
  });
  return { min, max, outside, first };
}

/**
 * f(l, v) against f(v, l): the largest relative difference, and the first pair past RECIPROCITY_TOLERANCE.
 * @param {import('./slots.js').Slot} slot @param {number[][]} inputs the pairs, then the same pairs swapped
 * @param {Float32Array} values @param {number} at
 */
export function reciprocityReport(slot, inputs, values, at) {
  const n = inputs.length / 2;
  let maxRel = 0;
  /** @type {{ inputs: Record<string, number>, values: number[] } | null} */
  let first = null;
  for (let i = 0; i < n; i++) {
    const [a, b] = [outputsAt(values, at + i, slot.outputs), outputsAt(values, at + n + i, slot.outputs)];
    a.forEach((x, o) => {
      const y = b[o];
      const scale = Math.max(Math.abs(x), Math.abs(y));
      const rel = x === y ? 0 : Number.isFinite(x - y) ? Math.abs(x - y) / scale : Infinity;
      maxRel = Math.max(maxRel, rel);
      if (rel > RECIPROCITY_TOLERANCE) first ??= { inputs: named(slot, inputs[i]), values: [x, y] };
    });
  }
  return { maxRel, first };
}

/**
 * The white furnace: the albedo at each view angle (each channel), and the largest.
 * @param {NonNullable<ReturnType<typeof import('./check-inputs.js').checkPlan>['furnace']>} parts
 * @param {Float32Array} values
 */
export function furnaceReport(parts, values) {
  const byView = parts.map(({ thetaV, weights, start }) => ({
    thetaV,
    albedo: [0, 1, 2].map((o) => weights.reduce((sum, w, i) => sum + w * values[(start + i) * 4 + o], 0)),
  }));
  const top = byView.reduce((a, b) => (Math.max(...b.albedo) > Math.max(...a.albedo) ? b : a));
  return { max: Math.max(...top.albedo), at: { thetaV: top.thetaV }, byView };
}

/**
 * The whole report of a check plan's values.
 * @param {ReturnType<typeof import('./check-inputs.js').checkPlan>} plan
 * @param {Float32Array} values 4 floats per input of plan.inputs
 * @param {string} [reference] a key of referenceOptions (default: the slot's)
 */
export function checkReport(plan, values, reference) {
  const slot = slotOf(plan.key);
  const key = reference ?? slot.reference;
  const slice = (/** @type {{ start: number, count: number }} */ p) => plan.inputs.slice(p.start, p.start + p.count);
  const stress = slice(plan.stress);
  const curveInputs = slice(plan.curve);
  const ref = referenceFunction(slot.key, key);
  return {
    nonFinite: nonFiniteReport(slot, stress, values, plan.stress.start),
    ...(plan.normalisation ? { normalisation: normalisationReport(plan.normalisation, values) } : {}),
    ...(slot.key === 'V' || slot.key === 'VAniso'
      ? { gRange: gRangeReport(slot, stress, values, plan.stress.start) }
      : {}),
    ...(slot.key === 'DAniso' && plan.normalisation
      ? {
          weakFurnace: weakFurnaceReport(
            /** @type {Parameters<typeof weakFurnaceReport>[0]} */ (plan.normalisation),
            values,
            key,
          ),
        }
      : {}),
    ...(plan.reciprocity
      ? { reciprocity: reciprocityReport(slot, slice(plan.reciprocity), values, plan.reciprocity.start) }
      : {}),
    ...(plan.furnace ? { furnace: furnaceReport(plan.furnace, values) } : {}),
    reference: referenceReport(slot, key, stress, values, plan.stress.start),
    curve: {
      x: plan.curve.x,
      xLabel: plan.curve.xLabel,
      custom: curveInputs.map((_, i) => values[(plan.curve.start + i) * 4]),
      reference: curveInputs.map((input) => ref(input)[0]),
    },
  };
}
