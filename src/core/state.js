// A widget's state is a plain object described by a schema. Values come in from the URL (strings),
// from the GUI, from code and from postMessage; all go through coerceState, which never throws:
// unknown keys are ignored, bad values fall back (to the current or default value) and are reported,
// numbers are clamped to their documented range.
//
// Field kinds: { type: 'number', min, max, step, default, label, unit }
//              { type: 'enum', options: { value: label }, default, label }
//              { type: 'bool', default, label }
//              { type: 'set', options: { value: label }, default: [values], label }  (URL: comma list)
//              { type: 'color', default: '#rrggbb', label }  (sRGB hex; the URL may drop the '#')

export function defaultState(schema) {
  return Object.fromEntries(
    Object.entries(schema).map(([k, f]) => [k, Array.isArray(f.default) ? [...f.default] : f.default]),
  );
}

const fmt = (v) => (typeof v === 'string' ? `"${v}"` : JSON.stringify(v));

function coerceField(key, f, raw, fallback) {
  const bad = (why) => ({ value: fallback, notice: `${f.label ?? key}: ${why}; kept ${fmt(fallback)}.` });
  switch (f.type) {
    case 'number': {
      const x = typeof raw === 'number' ? raw : typeof raw === 'string' && raw.trim() !== '' ? Number(raw) : NaN;
      if (!Number.isFinite(x)) return bad(`${fmt(raw)} is not a number`);
      const v = Math.min(Math.max(x, f.min), f.max);
      if (v !== x) return { value: v, notice: `${f.label ?? key}: ${x} is outside ${f.min}…${f.max}; clamped to ${v}.` };
      return { value: v };
    }
    case 'enum':
      return String(raw) in f.options ? { value: String(raw) } : bad(`${fmt(raw)} is not one of ${Object.keys(f.options).join(', ')}`);
    case 'bool': {
      if (typeof raw === 'boolean') return { value: raw };
      if (raw === '1' || raw === 'true') return { value: true };
      if (raw === '0' || raw === 'false') return { value: false };
      return bad(`${fmt(raw)} is not true/false`);
    }
    case 'set': {
      const items = Array.isArray(raw) ? raw.map(String) : typeof raw === 'string' ? raw.split(',').filter(Boolean) : null;
      if (!items) return bad(`${fmt(raw)} is not a list`);
      const known = [...new Set(items.filter((v) => v in f.options))];
      const unknown = items.filter((v) => !(v in f.options));
      if (unknown.length && !known.length) return bad(`${unknown.map(fmt).join(', ')} not recognised`);
      return unknown.length
        ? { value: known, notice: `${f.label ?? key}: ignored unknown ${unknown.map(fmt).join(', ')}.` }
        : { value: known };
    }
    case 'color': {
      const hex = typeof raw === 'string' ? raw.trim().replace(/^#?/, '#').toLowerCase() : '';
      return /^#[0-9a-f]{6}$/.test(hex) ? { value: hex } : bad(`${fmt(raw)} is not a colour like #rrggbb`);
    }
    default:
      throw new Error(`state: unknown field type ${f.type}`);
  }
}

/** Applies `input` (partial, strings or typed) on top of `base`. Returns { state, notices }. */
export function coerceState(schema, input, base = defaultState(schema)) {
  const state = { ...base };
  const notices = [];
  for (const [key, raw] of Object.entries(input ?? {})) {
    if (!Object.hasOwn(schema, key) || raw === undefined) continue;
    const { value, notice } = coerceField(key, schema[key], raw, base[key]);
    state[key] = value;
    if (notice) notices.push(notice);
  }
  return { state, notices };
}

const sameValue = (a, b) => (Array.isArray(a) ? a.join(',') === b.join(',') : a === b);

/** The state as URL parameters, only the fields that differ from their default. */
export function stateToParams(schema, state) {
  const params = new URLSearchParams();
  for (const [key, f] of Object.entries(schema)) {
    const v = state[key];
    if (v === undefined || sameValue(v, f.default)) continue;
    params.set(key, Array.isArray(v) ? v.join(',') : typeof v === 'boolean' ? (v ? '1' : '0') : String(v));
  }
  return params;
}

export const paramsToObject = (params) => Object.fromEntries(new URLSearchParams(params));
