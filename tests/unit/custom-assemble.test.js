// The custom chunk (src/core/custom/assemble.js): the user's first line is line 1 of source string 1 by the GLSL ES
// 3.00 rule for #line (spec §3.4: the line after `#line L S` is line L of string S), common.glsl comes before it
// once, and the program assembles with it like any chunk.
import { describe, expect, it } from 'vitest';
import { CUSTOM_CHUNK, customChunk, withCustomChunk } from '../../src/core/custom/assemble.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';

describe('customChunk', () => {
  it.each(Object.keys(SLOTS))('puts the %s starter right after #line 1 1, untouched', (key) => {
    const chunk = customChunk(key, SLOTS[key].starter);
    const lines = chunk.split('\n');
    const at = lines.indexOf('#line 1 1');
    expect(at).toBeGreaterThan(0);
    expect(lines.slice(at + 1, at + 1 + SLOTS[key].starter.split('\n').length).join('\n')).toBe(SLOTS[key].starter);
    expect(lines.at(-1)).toBe('#line 1 2');
  });
  it('normalises CRLF line ends so the line count stays the user’s', () => {
    const chunk = customChunk('D', 'float customD(float nh, float alpha) {\r\n  return nh;\r\n}');
    expect(chunk).toContain('#line 1 1\nfloat customD(float nh, float alpha) {\n  return nh;\n}\n#line 1 2');
  });
  it('refuses code with a preprocessor line (a programmer error: parseCustom refuses it first)', () => {
    expect(() => customChunk('D', '#include "ndf.glsl"')).toThrow(/preprocessor/);
  });
  it('assembles into a program with common.glsl once, before the user’s code', () => {
    const chunks = withCustomChunk(SHADER_CHUNKS, 'brdf', SLOTS.brdf.starter);
    const program = assembleGlsl(`#include "common.glsl"\n#include "${CUSTOM_CHUNK}"\nvoid main() {}`, { chunks });
    expect(program.match(/#define PI /g)).toHaveLength(1);
    expect(program.indexOf('#define PI')).toBeLessThan(program.indexOf('#line 1 1'));
    expect(program).toContain('uniform float albedo; // slider 0 1 1 "Albedo"');
  });
});
