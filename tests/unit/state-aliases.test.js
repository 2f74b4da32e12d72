import { describe, expect, it } from 'vitest';
import { coerceState, optionKey, paramsToObject, stateToParams } from '../../src/core/framework/state.js';

// A schema written here, not a widget's: the old spellings are the ones the material lab's links carried.
const schema = {
  diffuse: {
    type: 'enum',
    options: { lambert: 'Lambert', fresnelWeighted: 'Fresnel-weighted' },
    aliases: { 'fresnel-weighted': 'fresnelWeighted', ghost: 'missing' },
    default: 'lambert',
    label: 'Diffuse',
  },
  shown: {
    type: 'set',
    options: { a: 'A', bee: 'B' },
    aliases: { b: 'bee' },
    default: ['a'],
    label: 'Shown',
  },
};

describe('state aliases (old spellings of an option)', () => {
  it('reads an enum alias from a URL as its key, with no notice', () => {
    const { state, notices } = coerceState(schema, paramsToObject('diffuse=fresnel-weighted'));
    expect(state.diffuse).toBe('fresnelWeighted');
    expect(notices).toEqual([]);
  });
  it('reads set aliases as their keys, once each, beside keys given as they are', () => {
    const { state, notices } = coerceState(schema, { shown: 'b,a,bee' });
    expect(state.shown).toEqual(['bee', 'a']);
    expect(notices).toEqual([]);
    expect(coerceState(schema, { shown: ['b'] }).state.shown).toEqual(['bee']);
  });
  it('writes the key, never the alias, so a link round-trips to the new spelling', () => {
    const { state } = coerceState(schema, { diffuse: 'fresnel-weighted', shown: 'b' });
    const params = stateToParams(schema, state).toString();
    expect(params).toBe('diffuse=fresnelWeighted&shown=bee');
    expect(coerceState(schema, paramsToObject(params)).state).toEqual(state);
  });
  it('refuses what is neither an option nor an alias of one, and reports it as before', () => {
    for (const raw of ['ghost', 'fresnel_weighted', '__proto__', 'constructor']) {
      const { state, notices } = coerceState(schema, { diffuse: raw });
      expect(state.diffuse).toBe('lambert');
      expect(notices).toHaveLength(1);
      expect(notices[0]).toContain('not one of lambert, fresnelWeighted');
    }
    const mixed = coerceState(schema, { shown: 'b,zzz' });
    expect(mixed.state.shown).toEqual(['bee']);
    expect(mixed.notices[0]).toMatch(/ignored unknown "zzz"/);
  });
  it('optionKey names the option a value stands for, or nothing', () => {
    expect(optionKey(schema.diffuse, 'lambert')).toBe('lambert');
    expect(optionKey(schema.diffuse, 'fresnel-weighted')).toBe('fresnelWeighted');
    expect(optionKey(schema.diffuse, 'ghost')).toBeUndefined();
    expect(optionKey(schema.diffuse, 'hasOwnProperty')).toBeUndefined();
    expect(optionKey({ type: 'enum', options: { x: 'X' } }, 'x')).toBe('x');
  });
});
