// Assembles GLSL programs from the plain chunks in shaders/.
// `#include "name.glsl"` pulls a chunk in once; conditional blocks on `#define` switches are resolved here,
// in JS, so a program's source holds only the code its variant uses (a switched-off term is not in it).
// One pass in program order, as the C preprocessor reads it: a `#define NAME` met in active code counts for the
// conditionals after it, in that chunk and in the chunks included later.
import { SHADER_CHUNKS } from './shader-chunks.js';

const DIRECTIVE = /^\s*#\s*(ifdef|ifndef|if|elif|else|endif)\b\s*(.*)$/;
const DEFINED = /^(!?)\s*defined\s*\(\s*(\w+)\s*\)\s*$/;
const DEFINE = /^\s*#\s*define\s+(\w+)/;
const UNDEF = /^\s*#\s*undef\s+(\w+)/;
const INCLUDE = /^\s*#\s*include\s+"([\w.-]+)"\s*$/;
const ERROR = /^\s*#\s*error\b\s*"?([^"]*)"?\s*$/;
const IDENTIFIER = /\b[A-Za-z_]\w*\b/g;

/** The identifiers a line reads: its tokens outside comments, less the name a #define line defines. */
const readsOf = (line) =>
  line
    .replace(/\/\/.*$/, '')
    .replace(DEFINE, '')
    .match(IDENTIFIER) ?? [];

/** @param {string} kind @param {string} expr @param {{ has(name: string): boolean }} defined */
function condition(kind, expr, defined) {
  if (kind === 'ifdef') return defined.has(expr.trim());
  if (kind === 'ifndef') return !defined.has(expr.trim());
  // defined(A) || defined(B) && !defined(C): && binds tighter, as in C
  return expr.split('||').some((any) =>
    any.split('&&').every((term) => {
      const m = DEFINED.exec(term.trim());
      if (!m)
        throw new Error(`glsl: only 'defined(NAME)' conditions (with ||, &&) are supported, got '#${kind} ${expr}'`);
      return defined.has(m[2]) !== (m[1] === '!');
    }),
  );
}

/**
 * The #if/#elif/#else/#endif stack of one text: `step(line)` returns true when the line was a conditional
 * directive (consumed), and `active()` says whether the lines now are in the program.
 */
function conditionalStack(defined) {
  const stack = []; // { active, taken }
  const active = () => stack.every((s) => s.active);
  const step = (line) => {
    const m = DIRECTIVE.exec(line);
    if (!m) return false;
    const [, kind, expr] = m;
    if (kind === 'ifdef' || kind === 'ifndef' || kind === 'if') {
      // a block inside an inactive one is never taken (its condition is not even read)
      const on = active() && condition(kind, expr, defined);
      stack.push({ active: on, taken: on || !active() });
      return true;
    }
    const top = stack[stack.length - 1];
    if (!top) throw new Error(`glsl: #${kind} without #if`);
    if (kind === 'endif') stack.pop();
    else if (kind === 'else') [top.active, top.taken] = [!top.taken, true];
    else {
      const on = !top.taken && condition('if', expr, defined);
      [top.active, top.taken] = [on, top.taken || on];
    }
    return true;
  };
  const end = () => {
    if (stack.length) throw new Error('glsl: unterminated #if block');
  };
  return { step, active, end };
}

/**
 * Removes the inactive branches of #ifdef/#ifndef/#if defined()/#elif defined()/#else/#endif blocks (|| and &&
 * allowed).
 */
export function resolveConditionals(source, defines) {
  const defined = new Set(Object.keys(defines));
  const conditionals = conditionalStack(defined);
  const out = [];
  for (const line of source.split('\n')) if (!conditionals.step(line) && conditionals.active()) out.push(line);
  conditionals.end();
  return out.join('\n');
}

/**
 * A define's value as the program reads it: a switch is 1, a value a finite number or GLSL text (a call the
 * parity harness makes); `true` and the rest are refused, so that every host writes its switches one way.
 */
function defineValue(name, value) {
  if ((typeof value === 'number' && Number.isFinite(value)) || (typeof value === 'string' && value.trim()))
    return String(value);
  throw new Error(`glsl: define ${name} is ${JSON.stringify(value)}; a switch is 1, a value a number or GLSL text`);
}

/**
 * Resolves conditionals and includes of `source` against `chunks` (name -> text), each chunk once.
 * Returns the program text, prefixed with its defines (`#define NAME 1` for a switch, `#define NAME value`).
 * Refuses what it does not know: a define that no directive or token of the program's chunks reads (a misspelt
 * or stale switch would otherwise fall back silently), and an active #error (a term chain without a match).
 */
export function assembleGlsl(source, { defines = {}, chunks = SHADER_CHUNKS } = {}) {
  const defined = new Set(Object.keys(defines));
  const read = new Set();
  const included = new Set();
  const out = [];
  const walk = (text) => {
    const conditionals = conditionalStack(defined);
    for (const line of text.split('\n')) {
      for (const token of readsOf(line)) read.add(token);
      if (conditionals.step(line) || !conditionals.active()) continue;
      const include = INCLUDE.exec(line);
      if (!include) {
        if (ERROR.test(line)) throw new Error(`glsl: #error ${ERROR.exec(line)[1]}`);
        if (DEFINE.test(line)) defined.add(DEFINE.exec(line)[1]);
        if (UNDEF.test(line)) defined.delete(UNDEF.exec(line)[1]);
        out.push(line);
        continue;
      }
      const name = include[1];
      if (included.has(name)) continue;
      if (!(name in chunks)) throw new Error(`glsl: unknown chunk "${name}"`);
      included.add(name);
      walk(chunks[name]);
    }
    conditionals.end();
  };
  walk(source);
  const unread = Object.keys(defines).filter((name) => !read.has(name));
  if (unread.length) throw new Error(`glsl: define ${unread.join(', ')} is read by no chunk of this program`);
  const header = Object.entries(defines)
    .map(([k, v]) => `#define ${k} ${defineValue(k, v)}`)
    .join('\n');
  return `${header}\n${out.join('\n')}`;
}
