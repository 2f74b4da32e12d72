// Grades a shader exercise: the student's slot function, run on the GPU over the exercise's input grid, against
// the catalogue term in float64 at the same float32-rounded inputs. The GPU and the parser come in as functions
// (src/core/custom's evaluateCustom and parseCustom), so everything here is pure and runs in Node.
//
// An input passes when |yours − reference| ≤ abs + rel·|reference| on every channel (NaN and ±Inf never pass
// where the reference is finite). Score = the share of inputs that pass, in [0, 1]; passed = every input passes.
// The feedback names the worst input: the one whose error is the largest multiple of its tolerance.
import { termEntry, termLabel } from '../math/catalogue/index.js';
import { fmt } from './graders.js';
import { GRADED_SLOTS, channelsOf } from './shader-slots.js';
import { withHints } from './glsl-hints.js';
import { SLOTS } from '../core/custom/slots.js';

/** A number as feedback shows it (graders.js's fmt, 2 digits unless asked), with a short exponent: 3.2e7, 1e-4. */
export function fmtShort(x, digits = 2) {
  if (Number.isNaN(x)) return 'NaN';
  if (!Number.isFinite(x)) return x > 0 ? 'Inf' : '−Inf';
  return fmt(x, digits)
    .replace(/\.?0+e/, 'e')
    .replace('e+', 'e')
    .replace(/^-/, '−');
}

/** Yours and the reference with as many digits (2 to 8) as it takes to tell them apart. */
export function fmtPair(a, b) {
  let digits = 2;
  while (digits < 8 && fmtShort(a, digits) === fmtShort(b, digits)) digits++;
  return [fmtShort(a, digits), fmtShort(b, digits)];
}

/** An input as feedback shows it: up to 7 digits of its float32 value, so 0.999999 does not read as 1. */
export function fmtInput(x) {
  const v = Number(Math.fround(x).toPrecision(7));
  const a = Math.abs(v);
  const text = a !== 0 && (a < 1e-3 || a >= 1e5) ? v.toExponential().replace('e+', 'e') : String(v);
  return text.replace(/^-/, '−');
}

/** The values of one axis of the domain: evenly spaced over its range (ends included) and its stress values. */
export function axisValues({ range, steps, stress = [] }) {
  const even = range
    ? Array.from({ length: steps }, (_, i) => range[0] + ((range[1] - range[0]) * i) / (steps - 1))
    : [];
  return [...new Set([...even, ...stress].map((x) => Number(x.toPrecision(12))))].sort((a, b) => a - b);
}

/** Every point of the grid: the cartesian product of the axes' values, as { axis: value } records. */
export function domainGrid(domain, axisNames) {
  return axisNames.reduce(
    (points, name) => points.flatMap((p) => axisValues(domain[name]).map((x) => ({ ...p, [name]: x }))),
    [{}],
  );
}

/** The plot's points: its x axis over the domain's values and 48 between its ends, the other axes as given. */
export function plotPoints(exercise) {
  const { x, at } = exercise.plot;
  const values = axisValues(exercise.domain[x]);
  const [lo, hi] = [values[0], values[values.length - 1]];
  const fine = Array.from({ length: 48 }, (_, i) => lo + ((hi - lo) * i) / 47);
  return [...new Set([...values, ...fine])].sort((a, b) => a - b).map((v) => ({ ...at, [x]: v }));
}

/** The float64 reference at each point (its float32-rounded inputs). */
export function referenceValues(exercise, points) {
  const slot = GRADED_SLOTS[exercise.slot];
  const entry = termEntry(slot.family, exercise.reference.term);
  return points.map((p) => slot.reference(entry, p, exercise.reference.params));
}

/** How many tolerances apart a GPU value and its reference are (Infinity for NaN or ±Inf, where it is finite). */
export function excess(gpu, ref, { rel, abs }) {
  if (!Number.isFinite(gpu)) return gpu === ref ? 0 : Infinity;
  return Math.abs(gpu - ref) / (abs + rel * Math.abs(ref));
}

/**
 * Compares the GPU's output (4 floats per point; `channels` of them read) with the references. Returns
 * { count, passing, nonFinite, negative, worst: { index, value, reference, excess } | null, ratio }, where
 * ratio is the one factor between yours and the reference wherever both are clearly nonzero, or null.
 */
export function compareValues(gpu, refs, channels, tolerance) {
  let passing = 0;
  let nonFinite = 0;
  let negative = 0;
  let worst = null;
  const ratios = [];
  refs.forEach((ref, i) => {
    let pointExcess = 0;
    let pointValue = gpu[i * 4];
    for (let c = 0; c < channels; c++) {
      const g = gpu[i * 4 + c];
      const e = excess(g, ref, tolerance);
      if (e > pointExcess) [pointExcess, pointValue] = [e, g];
    }
    const g = gpu[i * 4];
    if (!Number.isFinite(g)) nonFinite++;
    else if (g < 0 && ref >= 0 && !(excess(g, ref, tolerance) <= 1)) negative++;
    if (pointExcess <= 1) passing++;
    if (Number.isFinite(g) && Math.abs(ref) > 100 * tolerance.abs && Math.abs(g) > 0) ratios.push(g / ref);
    if (!worst || pointExcess > worst.excess)
      worst = { index: i, value: pointValue, reference: ref, excess: pointExcess };
  });
  return { count: refs.length, passing, nonFinite, negative, worst, ratio: commonRatio(ratios) };
}

/** The factor all ratios share within 0.1%, when they all do and it is not 1; else null. */
function commonRatio(ratios) {
  if (ratios.length < 3) return null;
  const sorted = [...ratios].sort((a, b) => a - b);
  const median = sorted[Math.floor(sorted.length / 2)];
  const same = sorted.every((r) => Math.abs(r / median - 1) < 1e-3);
  return same && Math.abs(median - 1) > 1e-3 ? median : null;
}

/** "n·h = 1, α = 1e-4": a grid point in the axes' labels, in the slot's axis order. */
export function describePoint(slotKey, point) {
  return Object.entries(GRADED_SLOTS[slotKey].axes)
    .filter(([name]) => name in point)
    .map(([name, axis]) => `${axis.label} = ${fmtInput(point[name])}`)
    .join(', ');
}

const inputs = (n) => `${n.toLocaleString('en')} input${n === 1 ? '' : 's'}`;

const FACTORS = [
  [Math.PI, 'π'],
  [1 / Math.PI, '1/π'],
  [4, '4'],
  [0.25, '1/4'],
  [2, '2'],
  [0.5, '1/2'],
];

/** A word on a common factor: "a factor of π?" when it is one of the usual suspects. */
function ratioDetail(value, ratio) {
  const known = FACTORS.find(([f]) => Math.abs(ratio / f - 1) < 2e-3);
  const guess = known ? ` Is a factor of ${known[1]} missing or extra?` : '';
  return `Wherever both are clearly nonzero, your ${value} is ${fmtShort(ratio)}× the reference.${guess}`;
}

/** The feedback for a graded run: { passed, score, summary, details }. */
export function gradeFeedback(exercise, points, comparison) {
  const slot = GRADED_SLOTS[exercise.slot];
  const { count, passing, nonFinite, negative, worst, ratio } = comparison;
  const score = count ? passing / count : 0;
  const { rel, abs } = exercise.tolerance;
  const rule = `|yours − reference| ≤ ${fmtShort(abs)} + ${fmtShort(rel)}·|reference|`;
  const label = termLabel(slot.family, exercise.reference.term);
  if (passing === count)
    return {
      passed: true,
      score: 1,
      summary: `Right: your ${slot.value} matches ${label} at all ${count.toLocaleString('en')} inputs (${rule}).`,
      details: [],
    };
  const where = describePoint(exercise.slot, points[worst.index]);
  const [yours, reference] = fmtPair(worst.value, worst.reference);
  const details = [
    `${passing.toLocaleString('en')} of ${count.toLocaleString('en')} inputs match within ${rule}: ` +
      `score ${fmt(score, 2)}.`,
  ];
  if (nonFinite) details.push(`Your ${slot.value} is NaN or Inf at ${inputs(nonFinite)}.`);
  if (negative) details.push(`Your ${slot.value} is negative at ${inputs(negative)}.`);
  if (ratio !== null) details.push(ratioDetail(slot.value, ratio));
  return {
    passed: false,
    score,
    summary: `At ${where} your ${slot.value} is ${yours}; the reference is ${reference}.`,
    details,
  };
}

/**
 * Feedback for code that does not get to run: static-check problems or compile errors, at the student's lines,
 * each with its hint in plain words when it is a common mistake (glsl-hints.js), in the list and in the editor.
 */
export function problemFeedback(problems, what, code, slotKey) {
  const told = withHints(problems, code, SLOTS[slotKey].signature).map((p) =>
    p.hint ? { ...p, message: `${p.message}. In plain words: ${p.hint}` } : p,
  );
  const lines = told.map((p) => (p.line ? `Line ${p.line}: ${p.message}` : p.message));
  return { passed: false, score: 0, summary: what, details: lines, problems: told };
}

/**
 * Grades `code` for `exercise`. parse(slot, code) → { ok, problems }; evaluate(slot, code, inputs) →
 * Float32Array (4 floats per input) or { errors: [{ line, message }] }. Returns { passed, score, summary,
 * details, problems?, curve? } (curve: { x, xLabel, yours, reference } when the exercise has a plot).
 */
export function gradeShader(exercise, code, { parse, evaluate }) {
  const slot = GRADED_SLOTS[exercise.slot];
  const parsed = parse(exercise.slot, code);
  if (!parsed.ok)
    return problemFeedback(parsed.problems, 'Your code did not pass the static check:', code, exercise.slot);
  const points = domainGrid(exercise.domain, Object.keys(slot.axes));
  const extra = exercise.plot ? plotPoints(exercise) : [];
  const out = evaluate(exercise.slot, code, [...points, ...extra].map(slot.gpuArgs));
  if (!(out instanceof Float32Array))
    return problemFeedback(out.errors, 'Your code does not compile:', code, exercise.slot);
  const refs = referenceValues(exercise, points);
  const result = gradeFeedback(
    exercise,
    points,
    compareValues(out, refs, channelsOf(exercise.slot), exercise.tolerance),
  );
  if (!extra.length) return result;
  const base = points.length * 4;
  const curve = {
    x: extra.map((p) => p[exercise.plot.x]),
    xLabel: slot.axes[exercise.plot.x].label,
    yours: extra.map((_, i) => out[base + i * 4]),
    reference: referenceValues(exercise, extra),
  };
  return { ...result, curve };
}
