// Plain words for the commonest mistakes behind the GLSL parser's and compiler's terse messages: a missing ";" (the
// parser only notices at the next word), a whole number where GLSL wants a float (it converts none by itself:
// pow(x, 5) matches no pow) and a name that was never declared. The messages matched are the static check's
// (src/core/custom/parse.js) and ANGLE's, the compiler of Chrome, Edge and Firefox on every platform.

const INT_LITERAL = /(?<![\w.])\d+(?![\w.])/g; // 5, but not 5.0, 5., .5, 1e3 or x5
const DECLARED_ELSEWHERE = /^\s*(#|uniform\b)/; // lines that end without ";" by right

/** The argument names of a slot's signature: 'float customD(float nh, float alpha)' → ['nh', 'alpha']. */
const argumentsOf = (signature) => [...signature.matchAll(/(\w+)\s*[,)]/g)].map((m) => m[1]);

const withoutComment = (text) => text.replace(/\/\/.*$/, '').trim();

/** The nearest line above `line` (1-based) with code on it, as { number, text }, or null. */
function codeLineAbove(lines, line) {
  for (let i = line - 2; i >= 0; i--) if (withoutComment(lines[i])) return { number: i + 1, text: lines[i] };
  return null;
}

function parseHint(lines, line) {
  const above = codeLineAbove(lines, line);
  const text = above ? withoutComment(above.text) : '';
  if (above && !/[;{},(]$/.test(text) && !DECLARED_ELSEWHERE.test(text))
    return (
      `line ${above.number} ends without “;”. In GLSL every statement ends with a semicolon, and the parser only ` +
      `notices one is missing at the next word, here on line ${line}.`
    );
  return 'look for a missing “;” at the end of a statement, a missing “)” or “}”, or a misspelt word, on this line.';
}

function wholeNumberHint(lines, line, name) {
  const ints = [...new Set((lines[line - 1] ?? '').match(INT_LITERAL) ?? [])];
  if (ints.length)
    return (
      `GLSL turns no whole number into a float by itself: write ${ints.map((n) => `${n}.0`).join(', ')} for ` +
      `${ints.join(', ')}.`
    );
  if (name)
    return (
      `no ${name} takes arguments of these types: check its spelling, that it is declared above the function ` +
      'that calls it, and that each argument is a float (2.0, not 2) or a vector of the right size.'
    );
  return null;
}

function undeclaredHint(name, signature) {
  const args = argumentsOf(signature);
  return (
    `“${name}” is not declared before this line: check its spelling (GLSL tells capitals apart), declare it ` +
    `first (float ${name} = …;), or use the function’s arguments: ${args.join(', ')}.`
  );
}

/**
 * The hint for one problem ({ line, message }) of `code`, written for the slot of `signature`; null when its
 * message is none of the common mistakes.
 */
export function hintFor({ line, message }, code, signature) {
  const lines = code.replace(/\r\n?/g, '\n').split('\n');
  if (/^does not parse/.test(message)) return parseHint(lines, line);
  const undeclared = /^'(\w+)' : undeclared identifier/.exec(message);
  if (undeclared) return undeclaredHint(undeclared[1], signature);
  const overload = /^'(\w+)' : no matching overloaded function found/.exec(message);
  if (overload) return wholeNumberHint(lines, line, overload[1]);
  if (/cannot convert from '(?:const )?int'|operand of type '(?:const )?int'/.test(message))
    return wholeNumberHint(lines, line, null);
  return null;
}

/** The problems with their hints: `hint` added where one applies. */
export const withHints = (problems, code, signature) =>
  problems.map((p) => {
    const hint = p.line ? hintFor(p, code, signature) : null;
    return hint ? { ...p, hint } : p;
  });
