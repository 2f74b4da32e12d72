// Hostile values for the fuzz tests (unit and browser): what a crafted link or a hostile parent page may send,
// a seeded generator of partial states from them, and the rules a widget's state must keep whatever came in.
// The rules are written here from docs/security.md's description of the state, not from
// src/core/framework/state.js.
import LZString from 'lz-string';

/** A small seeded generator (mulberry32): the same seed gives the same inputs on every run. */
export function seededRandom(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export const PROTOTYPE_NAMES = [
  '__proto__',
  'constructor',
  'toString',
  'hasOwnProperty',
  'valueOf',
  'prototype',
  '__defineGetter__',
];
const LONG = 'x'.repeat(5000);
const HTML = [
  '<img src=x onerror="document.title=\'pwned\'">',
  '<script>document.title="pwned"</script>',
  '"><svg onload=alert(1)>',
];

/** As text (URL parameters) and typed (postMessage): every one of them is refused or clamped. */
export const NUMBER_TEXTS = [
  'NaN',
  'Infinity',
  '-Infinity',
  '1e309',
  '-1e309',
  '0x10',
  '0b11',
  '0o7',
  '١٢',
  '１２',
  '1_0',
  '',
  ' ',
  '1e',
  '.',
  '12abc',
  '1,5',
];
export const NUMBERS = [NaN, Infinity, -Infinity, Number.MAX_VALUE, -Number.MAX_VALUE, -0, 5e-324];
export const STRINGS = [...PROTOTYPE_NAMES, LONG, ...HTML, 'javascript:alert(1)', '\u0000', '\u202e'];

/** Lists with empty, repeated and inherited items, built around a real option `o`. */
export const listTexts = (o) => [
  ',',
  ',,',
  `${o},,${o}`,
  `${o},${o},${o}`,
  `${o},__proto__`,
  '__proto__,constructor',
  `,${o},`,
];
export const listArrays = (o) => [[], [''], [o, o], [o, '', o], [o, '__proto__'], [[o]], [null], [{}], [o, 7]];
/** Lists for a samples field: one short, one long, one with a bad item in the middle, one too large, one good. */
function sampleLists(f, typed) {
  const n = f.length;
  const good = Array.from({ length: n }, (_, i) => f.min + ((f.max - f.min) * i) / n);
  const bad = [good.with(n >> 1, 'NaN'), good.with(3, f.max * 2 + 1), good.with(2, '0x1')];
  const lists = [good.slice(1), [...good, f.min], ...bad, good];
  return typed ? [...lists, good.with(5, null), good.with(4, {})] : lists.map((l) => l.join(','));
}
export const ODD = [null, true, false, {}, [], { valueOf: 1 }, LONG];

/** Candidate raw values for field `f` (`typed`: as postMessage would carry them, else as URL text). */
export function candidates(f, typed) {
  const option = f.options ? Object.keys(f.options)[0] : 'x';
  const own = typed ? [...NUMBERS, ...STRINGS, ...ODD] : [...NUMBER_TEXTS, ...STRINGS];
  if (f.type === 'set') return [...own, ...(typed ? listArrays(option) : listTexts(option))];
  if (f.type === 'samples') return [...own, ...sampleLists(f, typed)];
  return own;
}

/** One seeded partial state of 1–4 hostile fields (sometimes a good value too), plus prototype keys now and then. */
export function hostilePartial(schema, random, typed) {
  const keys = Object.keys(schema);
  const pick = (list) => list[Math.floor(random() * list.length)];
  const partial = {};
  const n = 1 + Math.floor(random() * 4);
  for (let i = 0; i < n; i++) {
    const key = pick(keys);
    partial[key] = pick(candidates(schema[key], typed));
  }
  if (random() < 0.2) Object.defineProperty(partial, pick(PROTOTYPE_NAMES), { value: 'pwned', enumerable: true });
  return partial;
}

const DECIMAL = /^\s*[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?\s*$/i;

/** A user-written term's code (issue 13): at most 8000 characters, no control character but tab, LF and CR. */
const cleanCode = (code) =>
  typeof code === 'string' &&
  code.length <= 8000 &&
  [...code].every((ch) => (ch.charCodeAt(0) >= 32 ? ch !== '\u007f' : '\t\n\r'.includes(ch)));
/** As sent: the code, or `lz:` and its lz-string compression (URL-safe alphabet). */
const isCleanCode = (raw) =>
  typeof raw === 'string' &&
  raw.length <= 8000 &&
  cleanCode(raw.startsWith('lz:') ? LZString.decompressFromEncodedURIComponent(raw.slice(3)) || null : raw);
const PARAM_NAME = /^[A-Za-z_]\w*$/;
/** Slider values: at most 16 GLSL names (no `__`) → finite plain decimals, as a record or `name:value,…`. */
function isCleanParams(raw) {
  const plain = raw !== null && typeof raw === 'object' && Object.getPrototypeOf(raw) === Object.prototype;
  const entries =
    typeof raw === 'string'
      ? raw === ''
        ? []
        : raw.split(',').map((e) => e.split(':'))
      : plain
        ? Object.entries(raw)
        : null;
  const finite = (v) => (typeof v === 'number' ? Number.isFinite(v) : typeof v === 'string' && DECIMAL.test(v));
  return (
    entries !== null &&
    entries.length <= 16 &&
    entries.every((e) => e.length === 2 && PARAM_NAME.test(e[0]) && !e[0].includes('__') && finite(e[1]))
  );
}

/** True when `raw` is a value docs/security.md says a field takes as it is (no notice): the independent statement. */
export function isClean(f, raw) {
  const own = (v) => typeof v === 'string' && Object.prototype.hasOwnProperty.call(f.options, v);
  switch (f.type) {
    case 'number': {
      const x = typeof raw === 'number' ? raw : typeof raw === 'string' && DECIMAL.test(raw) ? Number(raw) : NaN;
      return Number.isFinite(x) && x >= f.min && x <= f.max;
    }
    case 'enum':
      return own(typeof raw === 'number' ? String(raw) : raw);
    case 'bool':
      return [true, false, '1', '0', 'true', 'false'].includes(raw);
    case 'set': {
      const items = typeof raw === 'string' ? raw.split(',').filter((s) => s !== '') : Array.isArray(raw) ? raw : null;
      return items !== null && items.every((v) => own(typeof v === 'number' ? String(v) : v));
    }
    case 'color':
      return typeof raw === 'string' && /^#?[0-9a-f]{6}$/i.test(raw.trim());
    case 'samples': {
      // docs/security.md: a comma list of exactly `length` plain decimals within the range, or the empty list
      const items = typeof raw === 'string' ? (raw === '' ? [] : raw.split(',')) : Array.isArray(raw) ? raw : null;
      const inRange = (v) => {
        const x = typeof v === 'number' ? v : typeof v === 'string' && DECIMAL.test(v) ? Number(v) : NaN;
        return Number.isFinite(x) && x >= f.min && x <= f.max;
      };
      return items !== null && (items.length === 0 || items.length === f.length) && items.every(inRange);
    }
    case 'text': // docs/security.md: at most maxLength letters, digits, spaces and . _ - ( ) + ,
      return typeof raw === 'string' && raw.length <= f.maxLength && /^[\p{L}\p{N} ._()+,-]*$/u.test(raw);
    case 'code':
      return isCleanCode(raw);
    case 'params':
      return isCleanParams(raw);
    default:
      return false;
  }
}

/** True when a field must keep its value for `raw`: not clean, and nothing in it to clamp or keep. */
export function isRefused(f, raw) {
  if (isClean(f, raw)) return false;
  if (f.type === 'number')
    return !Number.isFinite(
      typeof raw === 'number' ? raw : typeof raw === 'string' && DECIMAL.test(raw) ? Number(raw) : NaN,
    );
  if (f.type !== 'set') return true;
  const items = typeof raw === 'string' ? raw.split(',').filter((s) => s !== '') : Array.isArray(raw) ? raw : null;
  return items === null || !items.some((v) => isClean(f, [v]));
}

/** A partial state of refused values only (so the state must not move), seeded; prototype keys now and then. */
export function refusedPartial(schema, random, typed) {
  for (;;) {
    const partial = hostilePartial(schema, random, typed);
    const fields = Object.keys(partial).filter((k) => Object.hasOwn(schema, k));
    if (fields.every((k) => isRefused(schema[k], partial[k]))) return partial;
  }
}

/** One refused URL value for every field (text, rotating through its candidates), plus prototype-named keys. */
export function hostileQuery(schema, random) {
  const params = new URLSearchParams();
  for (const [key, f] of Object.entries(schema)) {
    const refused = candidates(f, false).filter((v) => isRefused(f, v));
    params.set(key, refused[Math.floor(random() * refused.length)]);
  }
  for (const name of PROTOTYPE_NAMES) params.set(name, 'pwned');
  return params;
}

/** A valid state change for `schema`: its first two fields moved off their defaults. */
export function goodPartial(schema) {
  const out = {};
  for (const [key, f] of Object.entries(schema).slice(0, 2)) {
    const options = f.options ? Object.keys(f.options) : [];
    const mid = Number(((f.min + f.max) / 2).toPrecision(3));
    out[key] =
      f.type === 'number'
        ? mid === f.default
          ? f.min
          : mid
        : f.type === 'enum'
          ? options.find((o) => o !== f.default)
          : f.type === 'bool'
            ? !f.default
            : f.type === 'set'
              ? [options.find((o) => !f.default.includes(o)) ?? options[0]]
              : '#336699';
  }
  return out;
}

/** Values that are odd but valid (the field takes them): empty and repeated list items, −0, a padded decimal. */
export function oddButValid(schema) {
  return Object.entries(schema).flatMap(([key, f]) => {
    const o = f.options ? Object.keys(f.options)[0] : null;
    if (f.type === 'set') return [{ [key]: ',' }, { [key]: `${o},,${o}` }, { [key]: [o, o, o] }];
    if (f.type === 'number' && f.min <= 0 && f.max >= 0) return [{ [key]: -0 }, { [key]: ' -0 ' }];
    return [];
  });
}

/** Numbers as JSON cannot carry them (NaN, ±Infinity, −0) and back: for sending values through DevTools. */
export const encodeNumbers = (value) =>
  JSON.stringify(value, (k, v) =>
    typeof v === 'number' && (!Number.isFinite(v) || Object.is(v, -0))
      ? { $n: Object.is(v, -0) ? '-0' : String(v) }
      : v,
  );
export const reviveNumbers = (k, v) =>
  v && typeof v === 'object' && typeof v.$n === 'string' && Object.keys(v).length === 1 ? Number(v.$n) : v;

/** What is wrong with a widget's whole state against its schema: [] when every value is one it may hold. */
export function stateProblems(schema, state) {
  const problems = [];
  const own = (f, v) => typeof v === 'string' && Object.prototype.hasOwnProperty.call(f.options, v);
  for (const [key, f] of Object.entries(schema)) {
    const v = state[key];
    const ok =
      f.type === 'number'
        ? typeof v === 'number' && Number.isFinite(v) && v >= f.min && v <= f.max && !Object.is(v, -0)
        : f.type === 'enum'
          ? own(f, v)
          : f.type === 'bool'
            ? typeof v === 'boolean'
            : f.type === 'set'
              ? Array.isArray(v) && v.every((x) => own(f, x)) && new Set(v).size === v.length
              : f.type === 'color'
                ? /^#[0-9a-f]{6}$/.test(v)
                : f.type === 'samples'
                  ? Array.isArray(v) &&
                    (v.length === 0 || v.length === f.length) &&
                    v.every((x) => typeof x === 'number' && x >= f.min && x <= f.max && !Object.is(x, -0))
                  : f.type === 'text'
                    ? isClean(f, v)
                    : f.type === 'code'
                      ? cleanCode(v)
                      : f.type === 'params'
                        ? isCleanParams(v) && Object.values(v).every((x) => !Object.is(x, -0))
                        : false;
    if (!ok) problems.push(`${key} = ${JSON.stringify(v)?.slice(0, 80)}`);
  }
  for (const key of Object.keys(state)) if (!Object.hasOwn(schema, key)) problems.push(`extra key ${key}`);
  return problems;
}

/** Object.prototype's own property names: a fuzz run must leave them exactly as they were. */
export const prototypeNames = () => Object.getOwnPropertyNames(Object.prototype).sort().join(',');
