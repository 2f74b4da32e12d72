// A user-written term in the widget state (src/core/custom/code-state.js, the `code` and `params` kinds of
// src/core/framework/state.js): the URL and postMessage round trip, compression only when it is shorter, the size
// limit with its message, and the last good value kept.
import { describe, expect, it } from 'vitest';
import LZString from 'lz-string';
import { COMPRESSED_PREFIX, MAX_CODE_CHARS, decodeCode, encodeCode } from '../../src/core/custom/code-state.js';
import { coerceState, defaultState, paramsToObject, stateToParams } from '../../src/core/framework/state.js';
import { parseMessage, unknownKeys } from '../../src/core/framework/embed-protocol.js';
import { SLOTS } from '../../src/core/custom/slots.js';

const schema = {
  code: { type: 'code', slot: 'D', default: SLOTS.D.starter, label: 'Custom D' },
  params: { type: 'params', default: {}, label: 'Sliders' },
  alpha: { type: 'number', min: 0, max: 1, default: 0.5 },
};
const longCode = `${SLOTS.brdf.starter}\n// ${'a comment that repeats itself, '.repeat(40)}\n`;

describe('encodeCode / decodeCode', () => {
  it('round-trips every starter and a long code through a URL query', () => {
    for (const code of [...Object.values(SLOTS).map((s) => s.starter), longCode, 'x', '']) {
      const query = new URLSearchParams({ c: encodeCode(code) }).toString();
      expect(decodeCode(new URLSearchParams(query).get('c'))).toEqual({ code });
    }
  });
  it('compresses only when the URL form is shorter, with lz-string (decompressed by lz-string itself)', () => {
    const short = 'float customD(float nh, float alpha) { return 1.0; }';
    expect(encodeCode(short)).toBe(short);
    const encoded = encodeCode(longCode);
    expect(encoded.startsWith(COMPRESSED_PREFIX)).toBe(true);
    expect(encoded.length).toBeLessThan(encodeURIComponent(longCode).length);
    expect(LZString.decompressFromEncodedURIComponent(encoded.slice(COMPRESSED_PREFIX.length))).toBe(longCode);
  });
  it('compresses a code that begins with the mark itself, so it cannot be misread', () => {
    const tricky = `${COMPRESSED_PREFIX}not compressed`;
    expect(decodeCode(encodeCode(tricky))).toEqual({ code: tricky });
  });
  it(`refuses past ${MAX_CODE_CHARS} characters, plain or once decompressed, with the count`, () => {
    const plain = 'x'.repeat(MAX_CODE_CHARS + 1);
    expect(decodeCode(plain)).toEqual({
      error: `the code has ${MAX_CODE_CHARS + 1} characters; at most ${MAX_CODE_CHARS} are taken`,
    });
    const bomb = COMPRESSED_PREFIX + LZString.compressToEncodedURIComponent('y'.repeat(100000));
    expect(bomb.length).toBeLessThan(MAX_CODE_CHARS); // small to carry, large once decompressed
    expect(decodeCode(bomb)).toEqual({
      error: `the code has 100000 characters once decompressed; at most ${MAX_CODE_CHARS}`,
    });
    expect(decodeCode(`${COMPRESSED_PREFIX}!!!`)).toEqual({
      error: 'the compressed code is damaged (it does not decompress)',
    });
    expect(decodeCode(42)).toEqual({ error: 'the code is not text' });
    expect(decodeCode('a\u0000b')).toEqual({ error: 'the code holds control characters that no shader takes' });
  });
});

describe('state: the code and params kinds', () => {
  const state = coerceState(schema, { code: longCode, params: { albedo: 0.25, k: -2 }, alpha: 0.3 }).state;
  it('round-trips through URL parameters (compressed code, name:value list)', () => {
    const params = stateToParams(schema, state);
    expect(params.get('code').startsWith(COMPRESSED_PREFIX)).toBe(true);
    expect(params.get('params')).toBe('albedo:0.25,k:-2');
    const back = coerceState(schema, paramsToObject(params.toString()));
    expect(back).toEqual({ state, notices: [] });
  });
  it('writes neither when they are at their defaults, and copies the default record', () => {
    const defaults = defaultState(schema);
    expect(stateToParams(schema, defaults).toString()).toBe('');
    expect(defaults.params).not.toBe(schema.params.default);
  });
  it('takes plain code from a parent frame set message, and reports the state as its query', () => {
    const msg = parseMessage({ type: 'shading-lab:set', state: { code: SLOTS.D.starter, params: 'a:1' } });
    expect(unknownKeys(schema, msg.state)).toEqual([]);
    const { state: next, notices } = coerceState(schema, msg.state, state);
    expect(notices).toEqual([]);
    expect(next.code).toBe(SLOTS.D.starter);
    expect(next.params).toEqual({ a: 1 });
  });
  it('keeps the last good code and sliders past the limit or with bad values, with a clear message', () => {
    const tooLong = 'x'.repeat(MAX_CODE_CHARS + 5);
    const { state: kept, notices } = coerceState(schema, { code: tooLong, params: { albedo: 'NaN' } }, state);
    expect(kept.code).toBe(state.code);
    expect(kept.params).toEqual(state.params);
    expect(notices).toEqual([
      `Custom D: the code has ${MAX_CODE_CHARS + 5} characters; at most ${MAX_CODE_CHARS} are taken; ` +
        'kept the code as it was.',
      expect.stringMatching(/^Sliders: albedo: "NaN" is not a finite decimal; kept/),
    ]);
  });
  it('refuses slider records that are not GLSL names, too many names, or not records', () => {
    const many = Object.fromEntries(Array.from({ length: 17 }, (_, i) => [`p${i}`, i]));
    for (const bad of [{ 'a-b': 1 }, { __proto__x: 1 }, many, [1, 2], 'a:1:2', 'a', { a: Infinity }]) {
      const { state: kept, notices } = coerceState(schema, { params: bad }, state);
      expect(kept.params).toEqual(state.params);
      expect(notices).toHaveLength(1);
    }
    expect(coerceState(schema, { params: JSON.parse('{"__proto__": 1}') }, state).state.params).toEqual(state.params);
  });
});
