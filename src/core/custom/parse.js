// @ts-check
// The static checks of a user-written term, before any GPU sees it: with a kept GLSL parser
// (@shaderfrog/glsl-parser) the code must parse, define the slot's function with its signature, and hold no loop
// that could hang the GPU; its slider lines become parameters. Every problem names the user's own line.
// A loop passes only in the one shape whose trip count is known before it runs:
// `for (int i = A; i < B; i++)` (<, <=, >, >=; ++, --, += C, -= C; A, B, C integer literals), its counter never
// assigned in the body, at most MAX_LOOP_ITERATIONS trips, nested loops (and the loops of a function called inside a
// loop) counted together. `while` and `do` have no such bound and are refused.
import { parse } from '@shaderfrog/glsl-parser/index.js';
import { visit } from '@shaderfrog/glsl-parser/ast/index.js';
import { slotOf } from './slots.js';
import { MAX_CODE_CHARS } from './code-state.js';

export const MAX_LOOP_ITERATIONS = 1024;
export const MAX_PARAMS = 16;
const MAX_LABEL = 40;

/** @typedef {{ name: string, min: number, max: number, value: number, label: string, line: number }} Param */
/** @typedef {{ line: number, message: string }} Problem */

const SLIDER =
  /^\s*uniform\s+float\s+([A-Za-z_]\w*)\s*;\s*\/\/\s*slider\s+(\S+)\s+(\S+)\s+(\S+)\s+"([^"\p{Cc}]*)"\s*$/u;
const SLIDER_FORM = 'uniform float name; // slider MIN MAX DEFAULT "Label"';
const UNIFORM_LINE = /^\s*uniform\b/;
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;
/** Names the host program owns: the app's uniforms (uName), GLSL's own, and what common.glsl and the harness give. */
const RESERVED = /^(gl_\w*|u[A-Z]\w*|PI|saturate|sin2FromCos|main|fragColor)$/;
/** Built-ins with an `out` parameter that could write a loop counter. */
const WRITES_ARGUMENT = new Set(['frexp', 'modf']);

/**
 * The slider of one `uniform` line, or a problem.
 * @param {string} text
 * @param {number} line
 * @returns {{ param: Param } | { problem: Problem }}
 */
function sliderOf(text, line) {
  const m = SLIDER.exec(text);
  if (!m) return { problem: { line, message: `a uniform must be a slider line: ${SLIDER_FORM}` } };
  const [, name, ...rest] = m;
  const label = rest[3].trim();
  const [min, max, value] = rest.slice(0, 3).map((s) => (DECIMAL.test(s) ? Number(s) : NaN));
  const bad = (/** @type {string} */ why) => ({ problem: { line, message: `slider '${name}': ${why}` } });
  if (![min, max, value].every(Number.isFinite)) return bad(`MIN MAX DEFAULT must be decimal numbers (${SLIDER_FORM})`);
  if (!(min < max)) return bad(`MIN (${min}) must be below MAX (${max})`);
  if (!(value >= min && value <= max)) return bad(`DEFAULT ${value} is outside ${min}…${max}`);
  if (!label || label.length > MAX_LABEL) return bad(`the label must have 1 to ${MAX_LABEL} characters`);
  return { param: { name, min, max, value, label, line } };
}

/**
 * Sliders and line-level refusals (preprocessor directives, uniforms that are no slider).
 * @param {string[]} lines
 */
function scanLines(lines) {
  /** @type {Param[]} */
  const params = [];
  /** @type {Problem[]} */
  const problems = [];
  lines.forEach((text, i) => {
    const line = i + 1;
    if (/^\s*#/.test(text)) problems.push({ line, message: 'preprocessor directives (#…) are not available here' });
    if (!UNIFORM_LINE.test(text)) return;
    const found = sliderOf(text, line);
    if ('problem' in found) problems.push(found.problem);
    else if (params.some((p) => p.name === found.param.name))
      problems.push({ line, message: `slider '${found.param.name}' is declared twice` });
    else if (params.length === MAX_PARAMS) problems.push({ line, message: `at most ${MAX_PARAMS} sliders` });
    else params.push(found.param);
  });
  return { params, problems };
}

/** @param {any} node @returns {number} */
const lineOf = (node) => node?.location?.start?.line ?? 1;

/** An integer literal's value (a leading minus allowed), else NaN. @param {any} node @returns {number} */
function intLiteral(node) {
  if (node?.type === 'int_constant' && /^\d+$/.test(node.token)) return Number(node.token);
  if (node?.type === 'unary' && node.operator.literal === '-') return -intLiteral(node.expression);
  return NaN;
}

/** @param {any} node @param {string} name */
const isName = (node, name) => node?.type === 'identifier' && node.identifier === name;

/**
 * The counter's step per trip: ++, --, += C, -= C; NaN for any other operation.
 * @param {any} op
 * @param {string} counter
 */
function stepOf(op, counter) {
  if ((op?.type === 'postfix' || op?.type === 'unary') && isName(op.expression, counter)) {
    const literal = op.type === 'postfix' ? op.postfix.literal : op.operator.literal;
    return literal === '++' ? 1 : literal === '--' ? -1 : NaN;
  }
  if (op?.type === 'assignment' && isName(op.left, counter)) {
    const c = intLiteral(op.right);
    return op.operator.literal === '+=' ? c : op.operator.literal === '-=' ? -c : NaN;
  }
  return NaN;
}

/**
 * How many times `for (int i = start; i OP bound; i += step)` runs; Infinity when it never ends.
 * @param {number} start @param {string} op @param {number} bound @param {number} step
 */
export function tripCount(start, op, bound, step) {
  const span = op === '<' || op === '<=' ? bound - start : start - bound;
  const by = op === '<' || op === '<=' ? step : -step;
  if (span < 0 || (span === 0 && (op === '<' || op === '>'))) return 0;
  if (!(by > 0)) return Infinity;
  return op === '<' || op === '>' ? Math.ceil(span / by) : Math.floor(span / by) + 1;
}

const LOOP_FORM = `loops must read for (int i = A; i < B; i++) with integer literals`;

/**
 * The trip count of a for statement, or the reason it is refused.
 * @param {any} node
 * @returns {{ counter: string, trips: number } | { why: string }}
 */
function forLoop(node) {
  const decl = node.init?.type === 'declarator_list' ? node.init : null;
  const one = decl?.declarations?.length === 1 ? decl.declarations[0] : null;
  const type = decl?.specified_type?.specifier?.specifier?.token;
  const counter = one?.identifier?.identifier;
  const start = intLiteral(one?.initializer);
  if (!one || type !== 'int' || !Number.isFinite(start)) return { why: `${LOOP_FORM} (an int counter from A)` };
  const cond = node.condition;
  const op = cond?.type === 'binary' ? cond.operator.literal : '';
  const bound = intLiteral(cond?.right);
  if (!['<', '<=', '>', '>='].includes(op) || !isName(cond.left, counter) || !Number.isFinite(bound))
    return { why: `${LOOP_FORM} (the condition compares ${counter} with an integer literal: <, <=, > or >=)` };
  const step = stepOf(node.operation, counter);
  if (!Number.isFinite(step)) return { why: `${LOOP_FORM} (the step is ${counter}++, ${counter}--, += C or -= C)` };
  const trips = tripCount(start, op, bound, step);
  if (trips === Infinity) return { why: `this loop never ends: ${counter} moves away from its bound` };
  return { counter, trips };
}

/**
 * The line where `counter` is written in `body`, or 0.
 * @param {any} body
 * @param {string} counter
 * @param {Set<string>} writers user functions with an out or inout parameter
 */
function counterWrite(body, counter, writers) {
  let at = 0;
  const mark = (/** @type {any} */ p) => (at ||= lineOf(p.node));
  visit(body, {
    assignment: { enter: (p) => isName(p.node.left, counter) && mark(p) },
    postfix: { enter: (p) => isName(p.node.expression, counter) && mark(p) },
    unary: {
      enter: (p) => ['++', '--'].includes(p.node.operator.literal) && isName(p.node.expression, counter) && mark(p),
    },
    function_call: {
      enter: (p) => {
        const id = /** @type {any} */ (p.node.identifier);
        const callee = id.identifier ?? id.specifier?.identifier; // a user function's name is a type_name node
        const writes = writers.has(callee) || WRITES_ARGUMENT.has(callee);
        if (writes && p.node.args.some((/** @type {any} */ a) => isName(a, counter))) mark(p);
      },
    },
  });
  return at;
}

/** @param {any} fn the function node @returns {string} its declaration as written, types and names */
const declarationOf = (fn) => {
  const header = fn.prototype.header;
  const params = (fn.prototype.parameters ?? []).map((/** @type {any} */ p) =>
    [
      ...(p.qualifier ?? []).map((/** @type {any} */ q) => q.token),
      p.specifier?.specifier?.token,
      p.identifier?.identifier,
    ]
      .filter(Boolean)
      .join(' '),
  );
  return `${header.returnType.specifier.specifier.token} ${header.name.identifier}(${params.join(', ')})`;
};

/**
 * Whether a function definition has the slot's signature (return type, argument types, only `in` qualifiers).
 * @param {any} fn
 * @param {import('./slots.js').Slot} slot
 */
function matchesSignature(fn, slot) {
  const params = fn.prototype.parameters ?? [];
  return (
    fn.prototype.header.returnType.specifier.specifier.token === slot.returns &&
    fn.prototype.header.returnType.qualifiers == null &&
    params.length === slot.args.length &&
    params.every(
      (/** @type {any} */ p, /** @type {number} */ i) =>
        p.specifier?.specifier?.token === slot.args[i].type &&
        p.specifier?.quantifier == null &&
        (p.qualifier ?? []).every((/** @type {any} */ q) => q.token === 'in' || q.token === 'const'),
    )
  );
}

/** @param {any} fn a function definition @returns {string} */
const nameOf = (fn) => fn.prototype.header.name.identifier;

/**
 * The user functions with an out or inout parameter: a call of one may write a loop counter.
 * @param {any[]} functions
 */
const writersOf = (functions) =>
  new Set(
    functions
      .filter((f) =>
        (f.prototype.parameters ?? []).some((/** @type {any} */ p) =>
          (p.qualifier ?? []).some((/** @type {any} */ q) => q.token === 'out' || q.token === 'inout'),
        ),
      )
      .map(nameOf),
  );

/**
 * The slot's function: there, and with the slot's signature.
 * @param {any[]} functions
 * @param {import('./slots.js').Slot} slot
 * @returns {Problem[]}
 */
function signatureProblems(functions, slot) {
  const own = functions.filter((f) => nameOf(f) === slot.fn);
  if (!own.length) return [{ line: 1, message: `${slot.fn} is missing: write ${slot.signature} { … }` }];
  return own
    .filter((f) => !matchesSignature(f, slot))
    .map((f) => ({ line: lineOf(f), message: `${slot.fn} must be ${slot.signature}, not ${declarationOf(f)}` }));
}

/**
 * The loops of one function: each refused one, the largest product of nested trip counts (its cost), and its
 * calls of other functions with the product of the loops around each.
 * @param {any} fn
 * @param {Set<string>} writers
 */
function functionLoops(fn, writers) {
  /** @type {Problem[]} */
  const problems = [];
  /** @type {{ callee: string, around: number, line: number }[]} */
  const calls = [];
  /** @type {number[]} trip counts of the enclosing loops */
  const nest = [];
  let cost = 1;
  const product = () => nest.reduce((a, b) => a * b, 1);
  const refuse = (/** @type {any} */ node, /** @type {string} */ message) =>
    problems.push({ line: lineOf(node), message });
  visit(fn.body, {
    while_statement: { enter: (p) => refuse(p.node, `'while' loops are refused (no constant bound); ${LOOP_FORM}`) },
    do_statement: { enter: (p) => refuse(p.node, `'do … while' loops are refused (no constant bound); ${LOOP_FORM}`) },
    for_statement: {
      enter: (p) => {
        const loop = forLoop(p.node);
        const trips = 'why' in loop ? 1 : loop.trips;
        if ('why' in loop) refuse(p.node, loop.why);
        else {
          const write = counterWrite(p.node.body, loop.counter, writers);
          if (write) problems.push({ line: write, message: `the loop counter ${loop.counter} is changed` });
        }
        const total = product() * trips;
        const nested = nest.length ? ' (nested loops multiply)' : '';
        if (total > MAX_LOOP_ITERATIONS) refuse(p.node, `${total} loop trips${nested}; at most ${MAX_LOOP_ITERATIONS}`);
        cost = Math.max(cost, total);
        nest.push(trips);
      },
      exit: () => void nest.pop(),
    },
    function_call: {
      enter: (p) => {
        const id = /** @type {any} */ (p.node.identifier);
        const callee = id.identifier ?? id.specifier?.identifier; // a user function's name is a type_name node
        if (typeof callee === 'string') calls.push({ callee, around: product(), line: lineOf(p.node) });
      },
    },
  });
  return { problems, cost, calls };
}

/**
 * Loops: each function's own, and calls that run a function's loops inside other loops (GLSL has no recursion:
 * the compiler refuses it, and a cycle here counts once).
 * @param {any[]} functions
 * @returns {Problem[]}
 */
function loopProblems(functions) {
  const writers = writersOf(functions);
  const loops = new Map(functions.map((f) => [nameOf(f), functionLoops(f, writers)]));
  /** @type {Map<string, number>} */
  const memo = new Map();
  /** @param {string} name @returns {number} the most trips one call of the function can run */
  const costOf = (name) => {
    const own = loops.get(name);
    if (!own) return 1; // a built-in
    if (memo.has(name)) return /** @type {number} */ (memo.get(name));
    memo.set(name, own.cost); // a cycle (refused by the compiler) stops here
    const cost = Math.max(own.cost, ...own.calls.map((c) => c.around * costOf(c.callee)));
    memo.set(name, cost);
    return cost;
  };
  const problems = [...loops.values()].flatMap((l) => l.problems);
  for (const { calls } of loops.values())
    for (const { callee, around, line } of calls) {
      const total = around * costOf(callee);
      if (around > 1 && total > MAX_LOOP_ITERATIONS) {
        const message = `${callee}() here runs ${total} loop trips (its loops × the loops around it)`;
        problems.push({ line, message: `${message}; at most ${MAX_LOOP_ITERATIONS}` });
      }
    }
  return problems;
}

/**
 * Names the host program owns, where the user declares them; uniforms that are not on a slider line of their own
 * (one hidden after other code on a line would read 0 for ever).
 * @param {any} ast
 * @param {Set<number>} uniformLines the lines that begin with `uniform` (scanLines judged them)
 * @returns {Problem[]}
 */
function declarationProblems(ast, uniformLines) {
  /** @type {Problem[]} */
  const problems = [];
  const reserved = (/** @type {any} */ node) => {
    const name = node?.identifier;
    if (typeof name === 'string' && RESERVED.test(name))
      problems.push({ line: lineOf(node), message: `'${name}' is a reserved name (gl_*, u + capital, PI, …)` });
  };
  const isUniform = (/** @type {any} */ list) =>
    (list.specified_type?.qualifiers ?? []).some((/** @type {any} */ q) => q.token === 'uniform');
  visit(ast, {
    declarator_list: {
      enter: (p) => {
        if (!isUniform(p.node)) return;
        for (const d of p.node.declarations ?? [])
          if (!uniformLines.has(lineOf(d)))
            problems.push({ line: lineOf(d), message: `a uniform must be a slider line of its own: ${SLIDER_FORM}` });
      },
    },
    declaration: { enter: (p) => reserved(p.node.identifier) },
    parameter_declaration: { enter: (p) => reserved(p.node.identifier) },
    function_header: { enter: (p) => reserved(p.node.name) },
  });
  return problems;
}

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
 * The static checks of `code` for a slot.
 * @param {string} slotKey a key of SLOTS
 * @param {string} code
 * @returns {{ ok: boolean, params: Param[], problems: Problem[] }}
 */
export function parseCustom(slotKey, code) {
  const slot = slotOf(slotKey);
  if (typeof code !== 'string') return { ok: false, params: [], problems: [{ line: 1, message: 'no code' }] };
  if (code.length > MAX_CODE_CHARS) {
    const message = `the code has ${code.length} characters; at most ${MAX_CODE_CHARS}`;
    return { ok: false, params: [], problems: [{ line: 1, message }] };
  }
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
