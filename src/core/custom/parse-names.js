// @ts-check
// The declarations of a user-written term: the slot's function with the slot's signature, no name the host program
// owns, and uniforms only on slider lines of their own.
import { visit } from '@shaderfrog/glsl-parser/ast/index.js';
import { lineOf, nameOf } from './parse-ast.js';
import { SLIDER_FORM } from './parse-sliders.js';

/** @typedef {import('./parse-sliders.js').Problem} Problem */

/** Names the host program owns: the app's uniforms (uName), GLSL's own, and what common.glsl and the harness give. */
const RESERVED = /^(gl_\w*|u[A-Z]\w*|PI|saturate|sin2FromCos|main|fragColor)$/;

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

/**
 * The slot's function: there, and with the slot's signature.
 * @param {any[]} functions
 * @param {import('./slots.js').Slot} slot
 * @returns {Problem[]}
 */
export function signatureProblems(functions, slot) {
  const own = functions.filter((f) => nameOf(f) === slot.fn);
  if (!own.length) return [{ line: 1, message: `${slot.fn} is missing: write ${slot.signature} { … }` }];
  return own
    .filter((f) => !matchesSignature(f, slot))
    .map((f) => ({ line: lineOf(f), message: `${slot.fn} must be ${slot.signature}, not ${declarationOf(f)}` }));
}

/**
 * Names the host program owns, where the user declares them; uniforms that are not on a slider line of their own
 * (one hidden after other code on a line would read 0 for ever).
 * @param {any} ast
 * @param {Set<number>} uniformLines the lines that begin with `uniform` (scanLines judged them)
 * @returns {Problem[]}
 */
export function declarationProblems(ast, uniformLines) {
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
