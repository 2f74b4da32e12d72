// The plain-words hints on GLSL errors (src/exercises/glsl-hints.js) for the three common mistakes, from the
// messages the tools really give: the static check's parser run here on the code, and ANGLE's compiler messages as
// Chromium 156 (SwiftShader) printed them for the same code in tests/browser/shader-exercises.test.js.
import { describe, expect, it } from 'vitest';
import { parseCustom } from '../../src/core/custom/parse.js';
import { hintFor, withHints } from '../../src/exercises/glsl-hints.js';
import { problemFeedback } from '../../src/exercises/shader-grader.js';
import { SLOTS } from '../../src/core/custom/slots.js';

const F = SLOTS.F.signature; // vec3 customF(vec3 f0, float lh)
const code = (...body) => ['vec3 customF(vec3 f0, float lh) {', ...body, '}', ''].join('\n');

describe('GLSL hints', () => {
  it('a missing ";": the parser stops on the next line; the hint names the line that lacks it', () => {
    const text = code('  float m = 1.0 - lh', '', '  return f0 + (1.0 - f0) * pow(m, 5.0);');
    const { problems } = parseCustom('F', text);
    expect(problems).toEqual([{ line: 4, message: 'does not parse: "r" is not expected here' }]);
    expect(hintFor(problems[0], text, F)).toMatch(/^line 2 ends without “;”\. .* here on line 4\.$/);
  });

  it('a whole number where a float is needed: pow(x, 5), float m = 1 and m * 2 each get "write 5.0 for 5"', () => {
    const cases = [
      [code('  return f0 + (1.0 - f0) * pow(1.0 - lh, 5);'), "'pow' : no matching overloaded function found", '5'],
      [code('  float m = 1;', '  return f0 * m;'), "'=' : cannot convert from 'const int' to 'highp float'", '1'],
      [
        code('  float m = 1.0 - lh;', '  return f0 * m * 2;'),
        "'*' : wrong operand types - no operation '*' exists that takes a left-hand operand of type 'highp " +
          "3-component vector of float' and a right operand of type 'const int' (or there is no acceptable conversion)",
        '2',
      ],
    ];
    for (const [text, message, n] of cases) {
      const line = text.split('\n').findIndex((l) => l.includes(` ${n}`) || l.includes(`, ${n}`)) + 1;
      expect(hintFor({ line, message }, text, F), message).toBe(
        `GLSL turns no whole number into a float by itself: write ${n}.0 for ${n}.`,
      );
    }
  });

  it('an undeclared name: its spelling, declaring it, or the slot’s own arguments (f0, lh)', () => {
    const text = code('  float m = 1.0 - lh;', '  return f0 + m5;');
    expect(hintFor({ line: 3, message: "'m5' : undeclared identifier" }, text, F)).toBe(
      '“m5” is not declared before this line: check its spelling (GLSL tells capitals apart), declare it first ' +
        '(float m5 = …;), or use the function’s arguments: f0, lh.',
    );
    expect(hintFor({ line: 2, message: "'x' : undeclared identifier" }, text, SLOTS.D.signature)).toMatch(
      /arguments: nh, alpha\.$/,
    );
  });

  it('no hint for other messages or outside the code; feedback and editor get the hint after the message', () => {
    const text = code('  return f0;');
    expect(hintFor({ line: 2, message: 'a while loop is not allowed' }, text, F)).toBeNull();
    expect(withHints([{ line: 0, message: "'m5' : undeclared identifier" }], text, F)).toEqual([
      { line: 0, message: "'m5' : undeclared identifier" },
    ]);
    const r = problemFeedback(
      [{ line: 2, message: "'m5' : undeclared identifier" }],
      'Your code does not compile:',
      text,
      'F',
    );
    expect(r.details[0]).toMatch(/^Line 2: 'm5' : undeclared identifier\. In plain words: “m5” is not declared/);
    expect(r.problems[0].message).toBe(r.details[0].replace('Line 2: ', ''));
  });
});
