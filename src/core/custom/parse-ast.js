// @ts-check
// What the static checks of a user-written term read off the GLSL parser's tree (@shaderfrog/glsl-parser): a
// node's line, integer literals, names.

/** @param {any} node @returns {number} */
export const lineOf = (node) => node?.location?.start?.line ?? 1;

/** An integer literal's value (a leading minus allowed), else NaN. @param {any} node @returns {number} */
export function intLiteral(node) {
  if (node?.type === 'int_constant' && /^\d+$/.test(node.token)) return Number(node.token);
  if (node?.type === 'unary' && node.operator.literal === '-') return -intLiteral(node.expression);
  return NaN;
}

/** @param {any} node @param {string} name */
export const isName = (node, name) => node?.type === 'identifier' && node.identifier === name;

/** @param {any} fn a function definition @returns {string} */
export const nameOf = (fn) => fn.prototype.header.name.identifier;
