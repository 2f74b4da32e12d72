// @ts-check
// The loops of a user-written term: a loop passes only in the one shape whose trip count is known before it runs,
// `for (int i = A; i < B; i++)` (<, <=, >, >=; ++, --, += C, -= C; A, B, C integer literals), its counter never
// assigned in the body, at most MAX_LOOP_ITERATIONS trips, nested loops (and the loops of a function called inside a
// loop) counted together. `while` and `do` have no such bound and are refused.
import { visit } from '@shaderfrog/glsl-parser/ast/index.js';
import { intLiteral, isName, lineOf, nameOf } from './parse-ast.js';

/** @typedef {import('./parse-sliders.js').Problem} Problem */

export const MAX_LOOP_ITERATIONS = 1024;
/** Built-ins with an `out` parameter that could write a loop counter. */
const WRITES_ARGUMENT = new Set(['frexp', 'modf']);

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
export function loopProblems(functions) {
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
