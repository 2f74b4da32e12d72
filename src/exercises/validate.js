// Checks an exercise file (parsed JSON) against the format in docs/exercises.md. Never throws: returns
// { exercise, errors }, each error naming the field and what is wrong, so a lecturer can fix the file.
import { CHAPTERS } from '../widgets/chapters.js';
import { coerceState, currentNames, defaultState, fieldOf, optionKey, showValue } from '../core/framework/state.js';
import { GRADERS, isGraderName } from './graders.js';
import { SHADER_FIELDS, shaderProblems } from './validate-shader.js';

export const FIELDS = [
  'id',
  'chapter',
  'title',
  'prompt',
  'widget',
  'state',
  'locked',
  'grader',
  'params',
  'tolerance',
  'points',
];
/** The fields of a set that is an index: { title, passMark, exercises: [...] }. */
export const SET_FIELDS = ['title', 'passMark', 'exercises'];
export const MAX_POINTS = 100;

const show = showValue;
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const sameValue = (a, b) =>
  JSON.stringify(Array.isArray(a) ? [...a].sort() : a) === JSON.stringify(Array.isArray(b) ? [...b].sort() : b);

/**
 * Why `value` does not fit state field `f` (src/core/framework/state.js kinds), or null. Strict: no strings for
 * numbers.
 */
export function fieldProblem(f, value) {
  switch (f.type) {
    case 'number':
      if (typeof value !== 'number' || !Number.isFinite(value)) return `${show(value)} is not a number`;
      return value < f.min || value > f.max ? `${value} is outside ${f.min}…${f.max}` : null;
    case 'enum':
      if (optionKey(f, value) !== undefined) return null;
      return `${show(value)} is not one of ${Object.keys(f.options).join(', ')}`;
    case 'bool':
      return typeof value === 'boolean' ? null : `${show(value)} is not true or false`;
    case 'set': {
      if (!Array.isArray(value)) return `${show(value)} is not a list`;
      const unknown = value.filter((v) => optionKey(f, v) === undefined);
      return unknown.length ? `${unknown.map(show).join(', ')} not among ${Object.keys(f.options).join(', ')}` : null;
    }
    case 'color':
      return typeof value === 'string' && /^#[0-9a-f]{6}$/i.test(value)
        ? null
        : `${show(value)} is not a colour like "#rrggbb"`;
    case 'samples':
    case 'text': // as a link would carry them (a samples list's items may be numbers)
      return (
        coerceState({ value: f }, { value })
          .notices[0]?.replace(/^[^:]*: /, '')
          .replace(/; kept .*$/, '') ?? null
      );
    default:
      return `unknown field type ${f.type}`;
  }
}

/** A valid value with an enum's or a set's old spellings (`aliases`) as their options' keys. */
const ownOptions = (f, value) =>
  f.type === 'enum' ? optionKey(f, value) : f.type === 'set' ? value.map((v) => optionKey(f, v)) : value;

function requiredText(raw, key, errors) {
  if (typeof raw[key] !== 'string' || !raw[key].trim()) errors.push(`${key}: missing (a non-empty string)`);
}

/** The fields every kind shares: unknown keys (of the kind's `fields`), id, chapter, title and prompt. */
function sharedProblems(raw, fields, errors) {
  for (const key of Object.keys(raw))
    if (!fields.includes(key)) errors.push(`${key}: unknown field (fields: ${fields.join(', ')})`);
  if (typeof raw.id !== 'string' || !/^[a-z0-9][a-z0-9-]*$/.test(raw.id)) {
    const what = raw.id === undefined ? 'missing' : `${show(raw.id)} is not`;
    errors.push(`id: ${what} a name of lower-case letters, digits and dashes`);
  }
  const chapters = CHAPTERS.map((c) => c.key);
  if (!chapters.includes(raw.chapter)) {
    const what = raw.chapter === undefined ? 'missing' : `${show(raw.chapter)} is not a chapter`;
    errors.push(`chapter: ${what} (chapters: ${chapters.join(', ')})`);
  }
  requiredText(raw, 'title', errors);
  requiredText(raw, 'prompt', errors);
  const p = raw.points;
  if (p !== undefined && !(typeof p === 'number' && p > 0 && p <= MAX_POINTS))
    errors.push(`points: ${show(p)} is not a number of points above 0 and at most ${MAX_POINTS}`);
}

/**
 * The set's own fields, when it is an index ({ "exercises": [...] }, docs/exercises.md): an optional title and a
 * pass mark in percent. Returns { title (null if none), passMark (null if none), errors }.
 */
export function validateSetFields(json) {
  const index = isObject(json) && Array.isArray(json.exercises);
  if (!index) return { title: null, passMark: null, errors: [] };
  const errors = [];
  for (const key of Object.keys(json))
    if (!SET_FIELDS.includes(key)) errors.push(`${key}: unknown field of a set (fields: ${SET_FIELDS.join(', ')})`);
  const { title, passMark } = json;
  if (title !== undefined && (typeof title !== 'string' || !title.trim()))
    errors.push(`title: ${show(title)} is not a non-empty string`);
  const markOk = passMark === undefined || (typeof passMark === 'number' && passMark >= 0 && passMark <= 100);
  if (!markOk) errors.push(`passMark: ${show(passMark)} is not a percentage 0…100`);
  return {
    title: typeof title === 'string' && title.trim() ? title.trim() : null,
    passMark: markOk && passMark !== undefined ? passMark : null,
    errors,
  };
}

/** The fields of a widget exercise that stand alone: the shared ones and tolerance. */
function headerProblems(raw, errors) {
  sharedProblems(raw, FIELDS, errors);
  if (raw.tolerance === undefined) errors.push('tolerance: missing (a positive number)');
  else if (typeof raw.tolerance !== 'number' || !(raw.tolerance > 0) || !Number.isFinite(raw.tolerance))
    errors.push(`tolerance: ${show(raw.tolerance)} is not a positive number`);
}

/** The grader named, or null (with the problem in `errors`). */
function graderOf(raw, errors) {
  if (isGraderName(raw.grader)) return GRADERS[raw.grader];
  const what = raw.grader === undefined ? 'missing' : `unknown grader ${show(raw.grader)}`;
  errors.push(`grader: ${what} (graders: ${Object.keys(GRADERS).join(', ')})`);
  return null;
}

/** The widget's state schema (null without a widget or for an unknown one), its state and its locked keys. */
async function widgetProblems(raw, grader, errors, schemaOf) {
  let schema = null;
  if (raw.widget !== undefined && raw.widget !== null) {
    schema = typeof raw.widget === 'string' ? await schemaOf(raw.widget) : null;
    if (!schema) errors.push(`widget: unknown widget ${show(raw.widget)}`);
  }
  const widgetFits = !grader?.widget || raw.widget === grader.widget;
  if (!widgetFits)
    errors.push(`widget: grader "${raw.grader}" reads the "${grader.widget}" widget, not ${show(raw.widget ?? null)}`);
  // an old file's keys under their fields' current names (a field's `formerly`), as a link's are
  const state = schema && isObject(raw.state) ? currentNames(schema, raw.state) : (raw.state ?? {});
  const locked =
    schema && Array.isArray(raw.locked)
      ? raw.locked.map((k) => (typeof k === 'string' ? fieldOf(schema, k, raw.state?.[k]) : k))
      : (raw.locked ?? []);
  if (!isObject(state)) errors.push('state: not an object of widget state keys');
  else if (Object.keys(state).length && !schema && raw.widget == null) errors.push('state: given without a widget');
  else if (schema) {
    for (const [key, value] of Object.entries(state)) {
      if (!Object.hasOwn(schema, key))
        errors.push(`state.${key}: unknown key for widget "${raw.widget}" (keys: ${Object.keys(schema).join(', ')})`);
      else {
        const why = fieldProblem(schema[key], value);
        if (why) errors.push(`state.${key}: ${why}`);
        else state[key] = ownOptions(schema[key], value);
      }
    }
  }
  if (!Array.isArray(locked) || locked.some((k) => typeof k !== 'string'))
    errors.push('locked: not a list of state keys');
  else if (schema) {
    for (const key of locked)
      if (!Object.hasOwn(schema, key)) errors.push(`locked: "${key}" is not a state key of widget "${raw.widget}"`);
  } else if (locked.length && raw.widget == null) errors.push('locked: given without a widget');
  return { schema, widgetFits, state, locked };
}

/** What the grader needs of the state: what the student sets stays free, what it assumes is fixed. */
function graderNeedsProblems(raw, grader, { schema, state, locked }, errors) {
  const full = { ...defaultState(schema), ...state };
  for (const key of grader.reads ?? [])
    if (locked.includes(key))
      errors.push(`locked: "${key}" is what the student sets for grader "${raw.grader}"; it must stay free`);
  for (const key of grader.given ?? [])
    if (!locked.includes(key))
      errors.push(`locked: must include "${key}" (grader "${raw.grader}" takes the question from it)`);
  for (const [key, value] of Object.entries(grader.requires ?? {})) {
    if (!sameValue(full[key], value))
      errors.push(`state.${key}: grader "${raw.grader}" needs ${show(value)}, got ${show(full[key])}`);
    else if (!locked.includes(key))
      errors.push(`locked: must include "${key}" (grader "${raw.grader}" assumes ${key} = ${show(value)})`);
  }
}

/**
 * raw: the parsed file. schemaOf(name): the widget's state schema (async; the page loads the widget module).
 * Returns { exercise (normalised: params with defaults, locked and state filled in), errors }.
 */
export async function validateExercise(raw, { schemaOf }) {
  if (!isObject(raw)) return { exercise: null, errors: ['the exercise is not a JSON object'] };
  if (raw.kind !== undefined) return validateOtherKind(raw);
  const errors = [];
  headerProblems(raw, errors);
  const grader = graderOf(raw, errors);
  const widget = await widgetProblems(raw, grader, errors, schemaOf);
  const { schema, widgetFits, state, locked } = widget;
  if (grader && widgetFits && schema && isObject(state) && Array.isArray(locked))
    graderNeedsProblems(raw, grader, widget, errors);

  const params = grader ? graderParams(raw, grader, errors) : {};

  // a grader that can tell whether its question has exactly one answer says so
  if (grader?.check && !errors.length) {
    for (const problem of grader.check(params, raw.tolerance)) errors.push(`params: ${problem}`);
  }

  if (errors.length) return { exercise: null, errors };
  const { id, chapter, title, prompt, tolerance, points = 1 } = raw;
  const exercise = { id, chapter, title, prompt, widget: raw.widget ?? null, state, locked, grader: raw.grader };
  return { exercise: { ...exercise, params, tolerance, points }, errors };
}

/** An exercise of another kind than a widget's: "shader" (validate-shader.js) is the one so far. */
function validateOtherKind(raw) {
  const errors = [];
  if (raw.kind !== 'shader') {
    errors.push(`kind: unknown kind ${show(raw.kind)} (kinds: shader; without "kind", a widget exercise)`);
    return { exercise: null, errors };
  }
  sharedProblems(raw, [...SHADER_FIELDS, 'points'], errors);
  const fields = shaderProblems(raw, errors);
  if (errors.length) return { exercise: null, errors };
  const { id, chapter, title, prompt, points = 1 } = raw;
  return { exercise: { id, chapter, title, prompt, points, ...fields }, errors };
}

/** The grader's params from raw.params, with its defaults filled in; each problem goes to `errors`. */
function graderParams(raw, grader, errors) {
  const params = {};
  const given = raw.params ?? {};
  if (!isObject(given)) {
    errors.push('params: not an object');
    return params;
  }
  for (const key of Object.keys(given)) {
    if (Object.hasOwn(grader.params, key)) continue;
    const known = Object.keys(grader.params).join(', ') || 'none';
    errors.push(`params.${key}: unknown for grader "${raw.grader}" (params: ${known})`);
  }
  for (const [key, f] of Object.entries(grader.params)) {
    if (given[key] === undefined) {
      if (f.required) errors.push(`params.${key}: missing (required by grader "${raw.grader}")`);
      else params[key] = f.default;
      continue;
    }
    const why = fieldProblem(f, given[key]);
    if (why) errors.push(`params.${key}: ${why}`);
    else params[key] = given[key];
  }
  return params;
}
