// The static checks of user-written terms (src/core/custom/parse.js): each refusal names the user's own line, the
// loop bound is counted exactly (1024 trips pass, 1025 do not), and slider lines become parameters.
import { describe, expect, it } from 'vitest';
import { parseCustom } from '../../src/core/custom/parse.js';
import { MAX_LOOP_ITERATIONS, tripCount } from '../../src/core/custom/parse-loops.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { MAX_CODE_CHARS } from '../../src/core/custom/code-state.js';

const D = (body) => `float customD(float nh, float alpha) {\n${body}\n}\n`;
const lines = (result) => result.problems.map((p) => p.line);

describe('parseCustom: the starters', () => {
  it.each(Object.keys(SLOTS))('the %s starter passes and declares the signature of its slot', (key) => {
    const result = parseCustom(key, SLOTS[key].starter);
    expect(result.problems).toEqual([]);
    expect(result.ok).toBe(true);
    expect(SLOTS[key].starter).toContain(SLOTS[key].signature);
  });
});

describe('parseCustom: loops (at most 1024 trips, counted by hand)', () => {
  const loop = (head) => D(`  float s = 0.0;\n  for (${head}) { s += 1.0; }\n  return s;`);
  it('1024 trips pass and 1025 are refused on the loop line', () => {
    expect(parseCustom('D', loop('int i = 0; i < 1024; i++')).ok).toBe(true);
    const refused = parseCustom('D', loop('int i = 0; i < 1025; i++'));
    expect(refused.ok).toBe(false);
    expect(refused.problems).toEqual([{ line: 3, message: expect.stringMatching(/1025 loop trips.*1024/) }]);
  });
  it('counts <=, >, >=, steps of C and downward loops like a C compiler would run them', () => {
    expect(parseCustom('D', loop('int i = 1; i <= 1024; ++i')).ok).toBe(true); // 1024 trips
    expect(parseCustom('D', loop('int i = 0; i <= 1024; i++')).ok).toBe(false); // 1025
    expect(parseCustom('D', loop('int i = 2048; i > 0; i -= 2')).ok).toBe(true); // 1024
    expect(parseCustom('D', loop('int i = 2049; i > 0; i -= 2')).ok).toBe(false); // 1025
    expect(parseCustom('D', loop('int i = -5; i >= -1029; i--')).ok).toBe(false); // 1025
    expect(tripCount(0, '<', 10, 3)).toBe(4); // 0 3 6 9
    expect(tripCount(0, '<=', 9, 3)).toBe(4); // 0 3 6 9
    expect(tripCount(10, '>', 0, -1)).toBe(10);
    expect(tripCount(5, '<', 5, 1)).toBe(0);
    expect(tripCount(0, '<', 10, -1)).toBe(Infinity);
  });
  it('refuses a counter moving away from its bound, a non-literal bound, a float counter', () => {
    for (const head of ['int i = 0; i < 10; i--', 'int i = 0; i < int(nh * 10.0); i++', 'float x = 0.0; x < 1.0; x++'])
      expect(lines(parseCustom('D', loop(head)))).toEqual([3]);
  });
  it('refuses while and do on their own lines', () => {
    const code = D('  float s = 1.0;\n  while (s > 0.0) s -= 0.1;\n  do { s += 1.0; } while (s < 2.0);\n  return s;');
    const result = parseCustom('D', code);
    expect(lines(result)).toEqual([3, 4]);
    expect(result.problems[0].message).toMatch(/'while'/);
    expect(result.problems[1].message).toMatch(/'do/);
  });
  it('refuses a counter written in the body (assignment, ++, an inout argument)', () => {
    const body = [
      '  float s = 0.0;',
      '  for (int i = 0; i < 10; i++) {',
      '    s += 1.0;',
      '    i += 1;',
      '  }',
      '  for (int j = 0; j < 10; j++) { bump(j); }',
      '  return s;',
    ].join('\n');
    const result = parseCustom('D', `void bump(inout int k) { k++; }\n${D(body)}`);
    expect(result.problems.map((p) => [p.line, p.message])).toEqual([
      [6, 'the loop counter i is changed'],
      [8, 'the loop counter j is changed'],
    ]);
  });
  it('counts a function’s loops inside the loops around its call: 32 × 32 pass, 33 × 32 refused at the call', () => {
    const helper = 'float sum32(float x) {\n  float s = 0.0;\n  for (int k = 0; k < 32; k++) s += x;\n  return s;\n}\n';
    const caller = (n) => D(`  float s = 0.0;\n  for (int i = 0; i < ${n}; i++) s += sum32(nh);\n  return s;`);
    expect(parseCustom('D', helper + caller(32)).ok).toBe(true);
    expect(parseCustom('D', helper + caller(33)).problems).toEqual([
      { line: 8, message: 'sum32() here runs 1056 loop trips (its loops × the loops around it); at most 1024' },
    ]);
  });
  it(`counts nested loops together: 32 × 32 = ${MAX_LOOP_ITERATIONS} pass, 33 × 32 do not`, () => {
    const nested = (n) =>
      D(`  float s = 0.0;\n  for (int i = 0; i < ${n}; i++)\n    for (int j = 0; j < 32; j++) s += 1.0;\n  return s;`);
    expect(parseCustom('D', nested(32)).ok).toBe(true);
    expect(parseCustom('D', nested(33)).problems).toEqual([{ line: 4, message: expect.stringMatching(/1056 loop/) }]);
  });
});

describe('parseCustom: signature, syntax and names', () => {
  it('names a missing slot function, and a wrong signature on its own line', () => {
    expect(parseCustom('D', 'float notD(float nh, float alpha) { return nh; }').problems).toEqual([
      { line: 1, message: 'customD is missing: write float customD(float nh, float alpha) { … }' },
    ]);
    const wrong = parseCustom('V', '// Smith\n\nfloat customV(float nl, float nv) { return 1.0; }');
    expect(wrong.problems).toEqual([
      {
        line: 3,
        message:
          'customV must be float customV(float nl, float nv, float alpha), not float customV(float nl, float nv)',
      },
    ]);
    expect(parseCustom('F', 'float customF(vec3 f0, float lh) { return 1.0; }').problems[0].line).toBe(1);
    expect(parseCustom('D', 'float customD(float nh, out float alpha) { return 1.0; }').ok).toBe(false);
  });
  it('puts a syntax error on the line of the broken statement', () => {
    const result = parseCustom('D', D('  float x = nh * 2.0;\n  return x'));
    expect(result.ok).toBe(false);
    expect(result.problems[0].line).toBe(3); // the statement that lacks its ';'
    expect(result.problems[0].message).toMatch(/does not parse/);
  });
  it('refuses reserved names (gl_*, u + capital, PI) and preprocessor lines where they are', () => {
    const code = `#define K 2.0\n${D('  float uScale = 2.0;\n  float gl_x = 1.0;\n  return nh;')}`;
    const result = parseCustom('D', code);
    expect(lines(result)).toEqual([1, 3, 4]);
    expect(result.problems[1].message).toMatch(/'uScale' is a reserved name/);
  });
  it(`refuses code past ${MAX_CODE_CHARS} characters with the count`, () => {
    const long = D(`  return nh;${' '.repeat(MAX_CODE_CHARS)}`);
    expect(parseCustom('D', long).problems).toEqual([
      { line: 1, message: `the code has ${long.length} characters; at most ${MAX_CODE_CHARS}` },
    ]);
  });
});

describe('parseCustom: slider lines', () => {
  it('reads name, range, default and label of each slider line', () => {
    const code = [
      'uniform float gain; // slider 0 2 1.5 "Gain"',
      '  uniform float k ;   //   slider -1e-2 .5 0 "Shape k (Low 2012)"',
      D('  return gain * k * nh;'),
    ].join('\n');
    expect(parseCustom('D', code)).toEqual({
      ok: true,
      problems: [],
      params: [
        { name: 'gain', min: 0, max: 2, value: 1.5, label: 'Gain', line: 1 },
        { name: 'k', min: -0.01, max: 0.5, value: 0, label: 'Shape k (Low 2012)', line: 2 },
      ],
    });
  });
  it('refuses a uniform hidden after other code on a line (it would read 0 for ever)', () => {
    const code = `float k = 1.0; uniform float gain;\n${D('  return gain * nh;')}`;
    expect(parseCustom('D', code).problems).toEqual([
      {
        line: 1,
        message: 'a uniform must be a slider line of its own: uniform float name; // slider MIN MAX DEFAULT "Label"',
      },
    ]);
  });
  it('refuses malformed slider lines, each on its line, with the reason', () => {
    const code = [
      'uniform float a; // slider 0 1 2 "A"',
      'uniform float b; // slider 1 0 0.5 "B"',
      'uniform float c; // slider 0 1 x "C"',
      'uniform float d;',
      'uniform vec3 e; // slider 0 1 0 "E"',
      'uniform float f; // slider 0 1 0 ""',
      'uniform float g; // slider 0 1 0 "G"',
      'uniform float g; // slider 0 1 0 "G again"',
      D('  return nh;'),
    ].join('\n');
    const result = parseCustom('D', code);
    expect(result.problems.map((p) => p.line)).toEqual([1, 2, 3, 4, 5, 6, 8]);
    expect(result.params.map((p) => p.name)).toEqual(['g']);
    expect(result.problems.map((p) => p.message)).toEqual([
      "slider 'a': DEFAULT 2 is outside 0…1",
      "slider 'b': MIN (1) must be below MAX (0)",
      'slider \'c\': MIN MAX DEFAULT must be decimal numbers (uniform float name; // slider MIN MAX DEFAULT "Label")',
      'a uniform must be a slider line: uniform float name; // slider MIN MAX DEFAULT "Label"',
      'a uniform must be a slider line: uniform float name; // slider MIN MAX DEFAULT "Label"',
      "slider 'f': the label must have 1 to 40 characters",
      "slider 'g' is declared twice",
    ]);
  });
});
