// @ts-check
// A widget's state is a plain object described by a schema. Values come in from the URL (strings),
// from the GUI, from code and from postMessage; all go through coerceState, which never throws:
// unknown keys are ignored, bad values fall back (to the current or default value) and are reported,
// numbers are clamped to their documented range. Input may be hostile (a crafted link, a page posting `set`):
// an enum or list value must be an OWN option (`__proto__`, `constructor`, `toString` are `in` every object),
// numbers are plain decimals (no hex, no Infinity), and a value echoed in a notice is cut short.
//
// The kinds of field (number, enum, set, bool, color, samples, text) are the Field typedefs of types.js; a
// user-written term adds two here: its code (`code`, carried compressed when long: src/core/custom/code-state.js)
// and its sliders' values (`params`).
// An enum or set field's `aliases` are old spellings of its options: each is read as its option, silently, so
// an old link keeps working; the state (and so every URL written from it) holds the option's own key.
// A field's `formerly` are its old names, read the same way by currentNames, the one place they are known. A name
// may be both a field and the old name of another (the lab's `diffuse` was the colour, is now the term): the value
// decides, as the field that takes it without a notice.

import { DECIMAL, MAX_PARAMS, decodeCode, encodeCode } from '../custom/code-state.js';

/** @typedef {import('./types.js').Schema} Schema */
/** @typedef {import('./types.js').Field} Field */
/** @typedef {import('./types.js').State} State */
/** @typedef {import('./types.js').StateValue} StateValue */
/** @typedef {{ value: any, notice?: string }} Coerced  the value taken (or kept), and why, when not as given */
/**
 * A user-written term's GLSL (no control: the code editor edits it); the URL carries encodeCode's form.
 * @typedef {{ type: 'code', slot: string, default: string, label?: string }} CodeField
 */
/**
 * The values of a user-written term's sliders, name → finite number (no control of its own: the panel makes one
 * per slider line); the URL carries `name:value,name:value`.
 * @typedef {{ type: 'params', default: Record<string, number>, label?: string }} ParamsField
 */
/** @typedef {Field | CodeField | ParamsField} AnyField */

const PARAM_NAME = /^[A-Za-z_]\w*$/;

/** A value as a new state holds it: lists and records copied. @param {any} v */
const copyValue = (v) => (Array.isArray(v) ? [...v] : v !== null && typeof v === 'object' ? { ...v } : v);

/**
 * Every field at its default (lists and records copied).
 * @param {Schema} schema
 * @returns {State}
 */
export function defaultState(schema) {
  return Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, copyValue(f.default)]));
}

const MAX_SHOWN = 60; // characters of a bad value repeated in a notice

/**
 * A value as a notice quotes it: strings in quotes, anything long cut short.
 * @param {unknown} v
 */
export function showValue(v) {
  let text;
  try {
    text = typeof v === 'string' ? `"${v}"` : (JSON.stringify(v) ?? String(v));
  } catch {
    text = Object.prototype.toString.call(v); // e.g. a BigInt or a cycle
  }
  return text.length > MAX_SHOWN ? `${text.slice(0, MAX_SHOWN)}… (${text.length} characters)` : text;
}
const fmt = showValue;

/**
 * True when `value` names an own option of `options` (a plain object of value → label).
 * @type {(options: Record<string, string>, value: unknown) => value is string}
 */
export const isOption = (options, value) => typeof value === 'string' && Object.hasOwn(options, value);

/**
 * The option an enum or set field's `value` names: the value itself, or the option its alias stands for.
 * @param {{ options: Record<string, string>, aliases?: Record<string, string> }} f
 * @param {unknown} value
 * @returns {string | undefined}
 */
export function optionKey(f, value) {
  if (isOption(f.options, value)) return value;
  const key = f.aliases && isOption(f.aliases, value) ? f.aliases[value] : undefined;
  return isOption(f.options, key) ? key : undefined;
}

// What a text field may hold: a name to show (a file name), never markup, a URL scheme or control characters.
const TEXT = /^[\p{L}\p{N} ._()+,-]*$/u;

/**
 * A number as given, or a plain-decimal string's value; NaN for anything else.
 * @param {unknown} raw
 */
export function parseNumber(raw) {
  if (typeof raw === 'number') return raw;
  return typeof raw === 'string' && DECIMAL.test(raw.trim()) ? Number(raw.trim()) : NaN;
}

/**
 * A list of exactly f.length plain decimals in f.min…f.max (or none at all), else refused whole.
 * @param {import('./types.js').SamplesField} f
 * @param {unknown} raw
 * @param {(why: string) => Coerced} bad
 * @returns {Coerced}
 */
function coerceSamples(f, raw, bad) {
  const items = Array.isArray(raw) ? raw : typeof raw === 'string' ? (raw === '' ? [] : raw.split(',')) : null;
  if (!items) return bad(`${fmt(raw)} is not a list`);
  if (items.length !== 0 && items.length !== f.length) return bad(`${items.length} values, not ${f.length}`);
  const values = items.map((v) => (typeof v === 'number' || typeof v === 'string' ? parseNumber(v) : NaN));
  const at = values.findIndex((x) => !(x >= f.min && x <= f.max)); // NaN fails too
  if (at >= 0) return bad(`value ${at + 1}, ${fmt(items[at])}, is not a decimal in ${f.min}…${f.max}`);
  return { value: values.map((x) => x || 0) };
}

/**
 * Slider values: a record name → number, or its URL form `name:value,…`; refused whole if any entry is bad.
 * @param {unknown} raw
 * @param {(why: string) => Coerced} bad
 * @returns {Coerced}
 */
function coerceParams(raw, bad) {
  let entries;
  if (typeof raw === 'string') entries = raw === '' ? [] : raw.split(',').map((item) => item.split(':'));
  else if (raw !== null && typeof raw === 'object' && Object.getPrototypeOf(raw) === Object.prototype)
    entries = Object.entries(raw);
  else return bad(`${fmt(raw)} is not a list of name:value`);
  if (entries.length > MAX_PARAMS) return bad(`${entries.length} values; at most ${MAX_PARAMS}`);
  /** @type {Record<string, number>} */
  const value = {};
  for (const entry of entries) {
    const [name, v, ...extra] = entry;
    const x = typeof v === 'number' || typeof v === 'string' ? parseNumber(v) : NaN;
    if (extra.length || typeof name !== 'string' || !PARAM_NAME.test(name) || name.includes('__'))
      return bad(`${fmt(entry.join(':'))} is not name:value with a GLSL name`);
    if (!Number.isFinite(x)) return bad(`${name}: ${fmt(v)} is not a finite decimal`);
    value[name] = x || 0; // `__proto__` cannot get here: GLSL reserves names with two underscores
  }
  return { value };
}

/**
 * A code field's value: the code a URL or a message carried (plain or compressed), within the size limit.
 * @param {string} label
 * @param {unknown} raw
 * @param {StateValue} fallback
 * @returns {Coerced}
 */
function coerceCode(label, raw, fallback) {
  const decoded = decodeCode(raw);
  if ('code' in decoded) return { value: decoded.code };
  return { value: fallback, notice: `${label}: ${decoded.error}; kept the code as it was.` };
}

/**
 * @param {string} key
 * @param {AnyField} f
 * @param {unknown} raw
 * @param {StateValue} fallback
 * @returns {Coerced}
 */
function coerceField(key, f, raw, fallback) {
  /** @param {string} why */
  const bad = (why) => ({ value: fallback, notice: `${f.label ?? key}: ${why}; kept ${fmt(fallback)}.` });
  switch (f.type) {
    case 'number': {
      const x = parseNumber(raw);
      const kind = typeof raw === 'number' ? 'finite' : 'decimal';
      if (!Number.isFinite(x)) return bad(`${fmt(raw)} is not a ${kind} number`);
      const v = Math.min(Math.max(x, f.min), f.max) || 0; // `|| 0`: -0 is stored as 0
      if (v !== x)
        return { value: v, notice: `${f.label ?? key}: ${x} is outside ${f.min}…${f.max}; clamped to ${v}.` };
      return { value: v };
    }
    case 'enum': {
      const v = typeof raw === 'number' ? String(raw) : raw; // an option like '64' may arrive as 64
      const key = optionKey(f, v);
      if (key !== undefined) return { value: key };
      return bad(`${fmt(raw)} is not one of ${Object.keys(f.options).join(', ')}`);
    }
    case 'bool': {
      if (typeof raw === 'boolean') return { value: raw };
      if (raw === '1' || raw === 'true') return { value: true };
      if (raw === '0' || raw === 'false') return { value: false };
      return bad(`${fmt(raw)} is not true/false`);
    }
    case 'set': {
      const items = Array.isArray(raw)
        ? raw.map((v) => (typeof v === 'number' ? String(v) : v))
        : typeof raw === 'string'
          ? raw.split(',').filter(Boolean)
          : null;
      if (!items) return bad(`${fmt(raw)} is not a list`);
      const keys = items.map((v) => optionKey(f, v));
      const known = [...new Set(keys.filter((k) => k !== undefined))];
      const unknown = [...new Set(items.filter((v, i) => keys[i] === undefined))];
      if (!unknown.length) return { value: known };
      const more = unknown.length > 4 ? ` and ${unknown.length - 4} more` : '';
      const named = unknown.slice(0, 4).map(fmt).join(', ') + more;
      if (!known.length) return bad(`${named} not recognised`);
      return { value: known, notice: `${f.label ?? key}: ignored unknown ${named}.` };
    }
    case 'color': {
      const hex = typeof raw === 'string' ? raw.trim().replace(/^#?/, '#').toLowerCase() : '';
      return /^#[0-9a-f]{6}$/.test(hex) ? { value: hex } : bad(`${fmt(raw)} is not a colour like #rrggbb`);
    }
    case 'samples':
      return coerceSamples(f, raw, bad);
    case 'text':
      if (typeof raw !== 'string' || raw.length > f.maxLength || !TEXT.test(raw))
        return bad(`${fmt(raw)} is not a name of at most ${f.maxLength} letters, digits, spaces or . _ - ( ) + ,`);
      return { value: raw };
    case 'code':
      return coerceCode(f.label ?? key, raw, fallback);
    case 'params':
      return coerceParams(raw, bad);
    default:
      throw new Error(`state: unknown field type ${/** @type {{ type: string }} */ (f).type}`);
  }
}

/**
 * The fields a name in an input may stand for: itself, if a field, then the fields that formerly had the name.
 * @param {Schema} schema
 * @param {string} name
 */
const fieldsNamed = (schema, name) => [
  ...(Object.hasOwn(schema, name) ? [name] : []),
  ...Object.keys(schema).filter((k) => schema[k].formerly?.includes(name)),
];

/**
 * The field a name in an input stands for, given its value (a name both a field and a former name: the field that
 * takes the value without a notice; without a value, the field of that name); a name of no field is itself.
 * @param {Schema} schema
 * @param {string} name
 * @param {unknown} [raw]
 */
export function fieldOf(schema, name, raw) {
  const fields = fieldsNamed(schema, name);
  if (fields.length < 2) return fields[0] ?? name;
  return fields.find((k) => !coerceField(k, schema[k], raw, schema[k].default).notice) ?? fields[0];
}

/**
 * `input` with every key under its field's current name (a field's `formerly`); other keys as they are. Where an
 * old name and the current one are both given, the current one wins.
 * @param {Schema} schema
 * @param {Partial<Record<string, unknown>> | null} [input]
 * @returns {Record<string, unknown>}
 */
export function currentNames(schema, input) {
  const old = new Map();
  const current = new Map(); // Maps, not objects: a key named __proto__ stays a key like any other
  for (const [name, raw] of Object.entries(input ?? {})) {
    const field = fieldOf(schema, name, raw);
    (field === name ? current : old).set(field, raw);
  }
  return Object.fromEntries([...old, ...current]);
}

/**
 * Applies `input` (partial, strings or typed, old field names read as their fields) on top of `base`.
 * @param {Schema} schema
 * @param {Partial<Record<string, unknown>> | null} [input]
 * @param {State} [base]
 * @returns {{ state: State, notices: string[] }}
 */
export function coerceState(schema, input, base = defaultState(schema)) {
  const state = { ...base };
  const notices = [];
  for (const [key, raw] of Object.entries(currentNames(schema, input))) {
    if (!Object.hasOwn(schema, key) || raw === undefined) continue;
    const { value, notice } = coerceField(key, schema[key], raw, base[key]);
    state[key] = value;
    if (notice) notices.push(notice);
  }
  return { state, notices };
}

/** A slider record in its URL form. @param {Record<string, number>} record */
const paramsText = (record) =>
  Object.entries(record)
    .map(([name, v]) => `${name}:${v}`)
    .join(',');

/** @type {(a: any, b: any) => boolean} */
const sameValue = (a, b) => {
  if (Array.isArray(a) && Array.isArray(b)) return a.join(',') === b.join(',');
  if (a && b && typeof a === 'object' && typeof b === 'object') return paramsText(a) === paramsText(b);
  return a === b;
};

/**
 * One field's value in a URL.
 * @param {AnyField} f
 * @param {any} v
 */
function paramText(f, v) {
  if (f.type === 'code') return encodeCode(v);
  if (f.type === 'params') return paramsText(v);
  return Array.isArray(v) ? v.join(',') : typeof v === 'boolean' ? (v ? '1' : '0') : String(v);
}

/**
 * The state as URL parameters, only the fields that differ from their default.
 * @param {Schema} schema
 * @param {State} state
 */
export function stateToParams(schema, state) {
  const params = new URLSearchParams();
  for (const [key, f] of Object.entries(schema)) {
    const v = state[key];
    if (v === undefined || sameValue(v, f.default)) continue;
    params.set(key, paramText(f, v));
  }
  return params;
}

/** @type {(params: string | URLSearchParams) => Record<string, string>} */
export const paramsToObject = (params) => Object.fromEntries(new URLSearchParams(params));
