// Checks the fields of a shader exercise ("kind": "shader", docs/exercises.md): the slot, the starter code, the
// catalogue term it is graded against, the input domain, the tolerance, the sources and the optional plot.
// Each problem names its field; validate.js has checked the fields every exercise shares.
import { showValue } from '../core/framework/state.js';
import { GRADED_SLOTS, GRADED_SLOT_KEYS, referenceProblems } from './shader-slots.js';
import { axisValues } from './shader-grader.js';
import { MAX_CODE_CHARS } from '../core/custom/code-state.js';

export const SHADER_FIELDS = [
  'id',
  'kind',
  'chapter',
  'title',
  'prompt',
  'sources',
  'slot',
  'starter',
  'reference',
  'domain',
  'tolerance',
  'plot',
];
/** The grid is one float render target: 16384 inputs draw in a few milliseconds even in software WebGL. */
export const MAX_GRID_POINTS = 16384;
export const MAX_STEPS = 101;
export const MAX_STRESS = 32;

const show = showValue;
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const finite = (x) => typeof x === 'number' && Number.isFinite(x);
const within = ([lo, hi], x) => finite(x) && x >= lo && x <= hi;

function sourcesProblems(sources, errors) {
  const ok = Array.isArray(sources) && sources.length && sources.every((s) => typeof s === 'string');
  if (!ok) return errors.push('sources: missing (a list of sources, each its authors and year, e.g. "Schlick 1994")');
  for (const s of sources)
    if (!/\p{L}.*\b(1[6-9]|20)\d\d\b/u.test(s)) errors.push(`sources: ${show(s)} names no author and year`);
}

function toleranceProblems(tolerance, errors) {
  if (!isObject(tolerance)) return errors.push('tolerance: missing (an object { "rel": number, "abs": number })');
  for (const key of Object.keys(tolerance))
    if (key !== 'rel' && key !== 'abs') errors.push(`tolerance.${key}: unknown (rel, abs)`);
  for (const key of ['rel', 'abs'])
    if (!finite(tolerance[key]) || tolerance[key] < 0 || tolerance[key] > 1)
      errors.push(`tolerance.${key}: ${show(tolerance[key])} is not a number within 0…1`);
  if (tolerance.rel === 0 && tolerance.abs === 0) errors.push('tolerance: rel and abs cannot both be 0');
}

/** One axis of the domain: { range: [min, max], steps, stress: [...] }, range and steps together, one at least. */
function axisProblems(name, spec, axis, errors) {
  const at = `domain.${name}`;
  if (!isObject(spec)) return errors.push(`${at}: not an object { "range": [min, max], "steps": n, "stress": [...] }`);
  for (const key of Object.keys(spec))
    if (!['range', 'steps', 'stress'].includes(key)) errors.push(`${at}.${key}: unknown (range, steps, stress)`);
  const limits = `${axis.limits[0]}…${axis.limits[1]}`;
  if (spec.range !== undefined) {
    const [lo, hi] = Array.isArray(spec.range) && spec.range.length === 2 ? spec.range : [NaN, NaN];
    if (!within(axis.limits, lo) || !within(axis.limits, hi) || !(lo < hi))
      errors.push(`${at}.range: ${show(spec.range)} is not [min, max] with min < max within ${limits}`);
    if (!Number.isInteger(spec.steps) || spec.steps < 2 || spec.steps > MAX_STEPS)
      errors.push(`${at}.steps: ${show(spec.steps)} is not a whole number within 2…${MAX_STEPS}`);
  } else if (spec.steps !== undefined) errors.push(`${at}.steps: given without a range`);
  if (spec.stress !== undefined) {
    if (!Array.isArray(spec.stress) || spec.stress.length > MAX_STRESS)
      errors.push(`${at}.stress: not a list of at most ${MAX_STRESS} numbers`);
    else
      for (const x of spec.stress)
        if (!within(axis.limits, x)) errors.push(`${at}.stress: ${show(x)} is not a number within ${limits}`);
  }
  if (spec.range === undefined && !spec.stress?.length) errors.push(`${at}: needs a range or stress values`);
}

function domainProblems(slotKey, domain, errors) {
  const axes = GRADED_SLOTS[slotKey].axes;
  if (!isObject(domain))
    return errors.push(`domain: missing (an object with the axes ${Object.keys(axes).join(', ')})`);
  const before = errors.length;
  for (const name of Object.keys(domain))
    if (!Object.hasOwn(axes, name))
      errors.push(`domain.${name}: not an axis of slot "${slotKey}" (axes: ${Object.keys(axes).join(', ')})`);
  for (const [name, axis] of Object.entries(axes)) {
    if (domain[name] === undefined) errors.push(`domain.${name}: missing (${axis.words})`);
    else axisProblems(name, domain[name], axis, errors);
  }
  if (errors.length > before) return;
  const size = Object.keys(axes).reduce((n, name) => n * axisValues(domain[name]).length, 1);
  if (size > MAX_GRID_POINTS)
    errors.push(`domain: ${size.toLocaleString('en')} inputs; the grid holds at most ${MAX_GRID_POINTS}`);
}

function plotProblems(slotKey, plot, errors) {
  if (plot === undefined) return;
  const axes = GRADED_SLOTS[slotKey].axes;
  if (!isObject(plot)) return errors.push('plot: not an object { "x": axis, "at": { other axes: value } }');
  for (const key of Object.keys(plot))
    if (!['x', 'at', 'logY'].includes(key)) errors.push(`plot.${key}: unknown (x, at, logY)`);
  if (!Object.hasOwn(axes, plot.x)) errors.push(`plot.x: ${show(plot.x)} is not an axis (${Object.keys(axes)})`);
  if (plot.logY !== undefined && typeof plot.logY !== 'boolean') errors.push('plot.logY: not true or false');
  const at = isObject(plot.at) ? plot.at : {};
  if (plot.at !== undefined && !isObject(plot.at)) errors.push('plot.at: not an object');
  for (const [name, axis] of Object.entries(axes)) {
    if (name === plot.x) continue;
    if (!within(axis.limits, at[name]))
      errors.push(`plot.at.${name}: ${show(at[name])} is not a number within ${axis.limits[0]}…${axis.limits[1]}`);
  }
  for (const name of Object.keys(at))
    if (!Object.hasOwn(axes, name) || name === plot.x) errors.push(`plot.at.${name}: not one of the other axes`);
}

function referenceOf(slotKey, reference, errors) {
  if (!isObject(reference) || typeof reference.term !== 'string')
    return errors.push('reference: missing (an object { "term": catalogue key, "params": { fixed parameters } })');
  for (const key of Object.keys(reference))
    if (key !== 'term' && key !== 'params') errors.push(`reference.${key}: unknown (term, params)`);
  const params = reference.params ?? {};
  if (!isObject(params)) return errors.push('reference.params: not an object');
  errors.push(...referenceProblems(slotKey, reference.term, params));
}

/** The shader fields' problems go to `errors`; returns the normalised fields (meaningful only without errors). */
export function shaderProblems(raw, errors) {
  sourcesProblems(raw.sources, errors);
  if (typeof raw.starter !== 'string') errors.push('starter: missing (the GLSL code the editor starts with)');
  else if (raw.starter.length > MAX_CODE_CHARS)
    errors.push(`starter: ${raw.starter.length} characters; at most ${MAX_CODE_CHARS}`);
  toleranceProblems(raw.tolerance, errors);
  if (!GRADED_SLOT_KEYS.includes(raw.slot)) {
    const what = raw.slot === undefined ? 'missing' : `${show(raw.slot)} is not a slot graded against a term`;
    errors.push(`slot: ${what} (slots: ${GRADED_SLOT_KEYS.join(', ')})`);
  } else {
    referenceOf(raw.slot, raw.reference, errors);
    domainProblems(raw.slot, raw.domain, errors);
    plotProblems(raw.slot, raw.plot, errors);
  }
  const { kind, sources, slot, starter, domain, tolerance, plot } = raw;
  const reference = { term: raw.reference?.term, params: raw.reference?.params ?? {} };
  return { kind, sources, slot, starter, reference, domain, tolerance, plot: plot ?? null };
}
