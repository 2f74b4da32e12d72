// The author page's drafts, pure: what a form's text becomes in an exercise (a number, a list, or the text as typed
// so that the validator can say what is wrong with it), where a validator message belongs, and a new exercise of
// each kind. Nothing typed is run: text is only ever parsed as a number or kept as text.
import { GRADERS } from '../graders.js';
import { SLOTS } from '../../core/custom/slots.js';
import { GRADED_SLOTS } from '../shader-slots.js';
import { defaultState } from '../../core/framework/state.js';

/** The kinds of exercise the format has, by how the student answers. */
export const KINDS = {
  number: 'Type a number',
  choice: 'Pick an option',
  state: 'Set the widget',
  shader: 'Write GLSL (a shader exercise)',
};

/** The graders whose answer is of `kind` (number, choice or state). */
export const gradersOf = (kind) => Object.keys(GRADERS).filter((name) => GRADERS[name].answer.kind === kind);

/** An exercise's kind: shader, or its grader's answer kind; `fallback` for a draft without a known grader. */
export function kindOf(raw, fallback = 'number') {
  if (raw?.kind === 'shader') return 'shader';
  return Object.hasOwn(GRADERS, raw?.grader) ? GRADERS[raw.grader].answer.kind : fallback;
}

/** A typed number: '' is nothing (undefined), "0,5" is 0.5, and text that is no number is kept for the validator. */
export function readNumber(text) {
  const t = String(text).trim();
  if (t === '') return undefined;
  const n = Number(t.replace(',', '.'));
  return Number.isFinite(n) && /^[-+]?[\d.,]+(e[-+]?\d+)?$/i.test(t) ? n : t;
}

/** A list typed with commas, semicolons or spaces between its items: numbers where they read as numbers. */
export function readNumberList(text) {
  const items = String(text)
    .split(/[\s;]+|,(?=\s|$)|,(?!\d)/)
    .filter(Boolean);
  return items.length ? items.map(readNumber) : undefined;
}

/** One item a line (blank lines dropped); undefined when there is none. */
export function readLines(text) {
  const lines = String(text)
    .split('\n')
    .map((l) => l.trim())
    .filter(Boolean);
  return lines.length ? lines : undefined;
}

/** Writes `value` at the dotted `path` of `target`, making objects on the way; undefined writes nothing. */
export function setPath(target, path, value) {
  if (value === undefined) return target;
  const keys = path.split('.');
  let at = target;
  for (const key of keys.slice(0, -1)) at = Object.hasOwn(at, key) ? at[key] : (at[key] = {});
  at[keys.at(-1)] = value;
  return target;
}

/** The field a validator message names ("state.theta: 5 is outside …" names state.theta), or null. */
export const pathOf = (message) => message.match(/^([A-Za-z][\w]*(?:\.[\w]+)*): /)?.[1] ?? null;

/**
 * The one of `paths` (the form's fields) a message about `path` belongs beside: the same path, else the nearest
 * enclosing one (state.theta → state). Null when the form has none.
 */
export function fieldFor(path, paths) {
  for (let p = path; p; p = p.includes('.') ? p.slice(0, p.lastIndexOf('.')) : '') if (paths.includes(p)) return p;
  return null;
}

/** The state an exercise keeps: the values that differ from the widget's defaults, and every locked one. */
export function compactState(schema, state, locked) {
  const base = defaultState(schema);
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  return Object.fromEntries(
    Object.entries(state).filter(([k, v]) => Object.hasOwn(schema, k) && (locked.includes(k) || !same(v, base[k]))),
  );
}

/** A shader exercise's slot with its defaults: the slot's starter and reference term, a grid over its axes. */
export function shaderDefaults(slot) {
  const domain = Object.fromEntries(
    Object.entries(GRADED_SLOTS[slot].axes).map(([name, axis]) => [
      name,
      // roughness at a few values (α = 0 is a mirror, where D is a spike); every other axis over 0…1
      name === 'alpha'
        ? { stress: [0.1, 0.3, 0.5, 1] }
        : { range: [Math.max(0, axis.limits[0]), Math.min(1, axis.limits[1])], steps: 11 },
    ]),
  );
  return { slot, starter: SLOTS[slot].starter, reference: { term: SLOTS[slot].reference }, domain };
}

/** A new exercise of `kind`, numbered n: a first grader or slot, its defaults; the lecturer's words left empty. */
export function newExercise(kind, n) {
  const head = { id: `exercise-${n}`, chapter: 'media', title: '', prompt: '' };
  if (kind === 'shader')
    return { ...head, kind: 'shader', sources: [], ...shaderDefaults('D'), tolerance: { rel: 1e-3, abs: 1e-5 } };
  const grader = gradersOf(kind)[0];
  const widget = GRADERS[grader].widget;
  return { ...head, ...(widget ? { widget } : {}), grader, tolerance: 0.05 };
}
