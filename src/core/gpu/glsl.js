// Assembles GLSL programs from the plain chunks in shaders/.
// `#include "name.glsl"` pulls a chunk in once; conditional blocks on `#define` switches are resolved here,
// in JS, so a program's source holds only the code its variant uses (a switched-off term is not in it).
import { SHADER_CHUNKS } from './shader-chunks.js';

const DIRECTIVE = /^\s*#\s*(ifdef|ifndef|if|elif|else|endif)\b\s*(.*)$/;
const DEFINED = /^(!?)\s*defined\s*\(\s*(\w+)\s*\)\s*$/;

function condition(kind, expr, defines) {
  if (kind === 'ifdef') return expr.trim() in defines;
  if (kind === 'ifndef') return !(expr.trim() in defines);
  // defined(A) || defined(B) && !defined(C): && binds tighter, as in C
  return expr.split('||').some((any) =>
    any.split('&&').every((term) => {
      const m = DEFINED.exec(term.trim());
      if (!m)
        throw new Error(`glsl: only 'defined(NAME)' conditions (with ||, &&) are supported, got '#${kind} ${expr}'`);
      return m[2] in defines !== (m[1] === '!');
    }),
  );
}

/** Removes the inactive branches of #ifdef/#ifndef/#if defined()/#elif defined()/#else/#endif blocks (|| and && allowed). */
export function resolveConditionals(source, defines) {
  const out = [];
  const stack = []; // { active, taken, parentActive }
  const active = () => stack.every((s) => s.active);
  for (const line of source.split('\n')) {
    const m = DIRECTIVE.exec(line);
    if (!m) {
      if (active()) out.push(line);
      continue;
    }
    const [, kind, expr] = m;
    if (kind === 'ifdef' || kind === 'ifndef' || kind === 'if') {
      const on = condition(kind, expr, defines);
      stack.push({ active: on, taken: on });
    } else {
      const top = stack[stack.length - 1];
      if (!top) throw new Error(`glsl: #${kind} without #if`);
      if (kind === 'endif') stack.pop();
      else if (kind === 'else') [top.active, top.taken] = [!top.taken, true];
      else {
        const on = !top.taken && condition('if', expr, defines);
        [top.active, top.taken] = [on, top.taken || on];
      }
    }
  }
  if (stack.length) throw new Error('glsl: unterminated #if block');
  return out.join('\n');
}

const INCLUDE = /^\s*#\s*include\s+"([\w.-]+)"\s*$/;

/**
 * Resolves conditionals and includes of `source` against `chunks` (name -> text), each chunk once.
 * Returns the program text, prefixed with the defines that have values the code may read.
 */
export function assembleGlsl(source, { defines = {}, chunks = SHADER_CHUNKS } = {}) {
  const included = new Set();
  const expand = (text) =>
    resolveConditionals(text, defines)
      .split('\n')
      .map((line) => {
        const m = INCLUDE.exec(line);
        if (!m) return line;
        const name = m[1];
        if (included.has(name)) return '';
        if (!(name in chunks)) throw new Error(`glsl: unknown chunk "${name}"`);
        included.add(name);
        return expand(chunks[name]);
      })
      .join('\n');
  const header = Object.entries(defines)
    .map(([k, v]) => `#define ${k}${v === true || v === '' ? '' : ` ${v}`}`)
    .join('\n');
  return `${header}\n${expand(source)}`;
}
