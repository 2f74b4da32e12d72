// @ts-check
// The static checks of a user-written term, before any GPU sees it: with a kept GLSL parser
// (@shaderfrog/glsl-parser) the code must parse, define the slot's function with its signature (parse-names.js),
// and hold no loop that could hang the GPU (parse-loops.js); its slider lines become parameters (parse-sliders.js).
// Every problem names the user's own line. A code is checked once: the verdict is kept by slot and code, so the
// panel, the runner and the GPU evaluation of one edit share it.
import { parse } from '@shaderfrog/glsl-parser/index.js';
import { slotOf } from './slots.js';
import { MAX_CODE_CHARS } from './code-state.js';
import { UNIFORM_LINE, scanLines } from './parse-sliders.js';
import { loopProblems } from './parse-loops.js';
import { declarationProblems, signatureProblems } from './parse-names.js';

/** @typedef {import('./parse-sliders.js').Param} Param */
/** @typedef {import('./parse-sliders.js').Problem} Problem */
/** @typedef {{ ok: boolean, params: Param[], problems: Problem[] }} Verdict */

/**
 * The problems of a parsed program: the slot's function, loops, reserved names, uniforms off a slider line.
 * @param {any} ast
 * @param {import('./slots.js').Slot} slot
 * @param {Set<number>} uniformLines the lines that begin with `uniform`
 * @returns {Problem[]}
 */
function checkProgram(ast, slot, uniformLines) {
  const functions = ast.program.filter((/** @type {any} */ s) => s.type === 'function');
  return [...signatureProblems(functions, slot), ...loopProblems(functions), ...declarationProblems(ast, uniformLines)];
}

/**
 * The parser's message, short: Peggy lists every token it would take, often a dozen.
 * @param {string} message
 */
function syntaxMessage(message) {
  const first = message.split('\n')[0].replace(/^Error:\s*/, '');
  const m = /^Expected (.*) but (.*) found\.$/.exec(first);
  if (!m) return `does not parse: ${first}`;
  const expected = m[1].split(/, (?:or )?| or /);
  if (expected.length > 4) return `does not parse: ${m[2]} is not expected here`;
  return `does not parse: expected ${m[1]}, found ${m[2]}`;
}

/**
 * The static checks of `code` for a slot, made afresh.
 * @param {import('./slots.js').Slot} slot
 * @param {string} code
 * @returns {Verdict}
 */
function checkCode(slot, code) {
  const text = code.replace(/\r\n?/g, '\n');
  const lines = text.split('\n');
  const { params, problems } = scanLines(lines);
  const uniformLines = new Set(lines.flatMap((line, i) => (UNIFORM_LINE.test(line) ? [i + 1] : [])));
  /** @type {any} */
  let ast = null;
  try {
    ast = parse(text.replace(/^\s*#.*$/gm, ''), { quiet: true, includeLocation: true, stage: 'fragment' });
  } catch (e) {
    const error = /** @type {{ message?: string, location?: { start?: { line?: number } } }} */ (e);
    problems.push({ line: error?.location?.start?.line ?? 1, message: syntaxMessage(String(error?.message ?? e)) });
  }
  if (ast) problems.push(...checkProgram(ast, slot, uniformLines));
  problems.sort((a, b) => a.line - b.line);
  return { ok: problems.length === 0, params, problems };
}

const KEEP = 32; // verdicts kept: the codes of every slot on a page, and the last few edits of each
/** @type {Map<string, Verdict>} by slot and code, oldest first */
const verdicts = new Map();
let parses = 0;

/**
 * A verdict that its callers share, frozen so that none can change another's.
 * @param {Verdict} v
 * @returns {Verdict}
 */
const frozen = (v) => {
  [...v.params, ...v.problems].forEach((x) => Object.freeze(x));
  Object.freeze(v.params);
  Object.freeze(v.problems);
  return Object.freeze(v);
};

/**
 * The static checks of `code` for a slot: parsed the first time this slot and code are asked about, then the
 * same verdict for every caller (the runner, the GPU evaluation, the panel and its sliders).
 * @param {string} slotKey a key of SLOTS
 * @param {string} code
 * @returns {Verdict}  frozen
 */
export function parseCustom(slotKey, code) {
  const slot = slotOf(slotKey);
  const refuse = (/** @type {string} */ message) => frozen({ ok: false, params: [], problems: [{ line: 1, message }] });
  if (typeof code !== 'string') return refuse('no code');
  if (code.length > MAX_CODE_CHARS) return refuse(`the code has ${code.length} characters; at most ${MAX_CODE_CHARS}`);
  const key = `${slotKey}\u0000${code}`;
  const known = verdicts.get(key);
  if (known) {
    verdicts.delete(key); // the most recently asked about goes last: the oldest is let go first
    verdicts.set(key, known);
    return known;
  }
  parses++;
  const verdict = frozen(checkCode(slot, code));
  verdicts.set(key, verdict);
  if (verdicts.size > KEEP) verdicts.delete(verdicts.keys().next().value ?? '');
  return verdict;
}

/** How many codes have been parsed on this page so far (a verdict asked for again is no parse). */
export const parseCount = () => parses;
