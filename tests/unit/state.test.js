import { describe, expect, it } from 'vitest';
import { coerceState, defaultState, paramsToObject, stateToParams } from '../../src/core/framework/state.js';
import { schema as zonesSchema } from '../../src/widgets/fresnel-zones/fresnel-zones.js';
import { schema as curvesSchema } from '../../src/widgets/fresnel-curves/fresnel-curves.js';

describe('widget state', () => {
  it('round-trips through URL parameters', () => {
    for (const schema of [zonesSchema, curvesSchema]) {
      const { state } = coerceState(schema, {
        mode: 'zones-lh',
        lightTheta: 123.4,
        materials: ['gold', 'water'],
        schlick: false,
      });
      const back = coerceState(schema, paramsToObject(stateToParams(schema, state).toString())).state;
      expect(back).toEqual(state);
    }
  });
  it('clamps numbers, keeps the previous value for bad ones, ignores unknown keys, and reports each', () => {
    const base = defaultState(zonesSchema);
    const { state, notices } = coerceState(
      zonesSchema,
      { lightTheta: '400', alpha: 'x', mode: 'banana', nonsense: '1' },
      base,
    );
    expect(state.lightTheta).toBe(180);
    expect(state.alpha).toBe(base.alpha);
    expect(state.mode).toBe(base.mode);
    expect('nonsense' in state).toBe(false);
    expect(notices).toHaveLength(3);
  });
  it('keeps the known part of a list and reports the rest', () => {
    const { state, notices } = coerceState(curvesSchema, { materials: 'gold,unobtainium' });
    expect(state.materials).toEqual(['gold']);
    expect(notices[0]).toMatch(/unobtainium/);
  });
  it('writes only what differs from the defaults', () => {
    expect(stateToParams(zonesSchema, defaultState(zonesSchema)).toString()).toBe('');
  });
});

describe('colour fields', () => {
  const schema = { tint: { type: 'color', default: '#808080', label: 'Tint' } };
  it('take #rrggbb or rrggbb (as a URL may carry it), lower-cased, and round-trip', () => {
    expect(coerceState(schema, { tint: 'A0B0C0' }).state.tint).toBe('#a0b0c0');
    const { state } = coerceState(schema, { tint: '#102030' });
    expect(coerceState(schema, paramsToObject(stateToParams(schema, state).toString())).state).toEqual(state);
  });
  it('keep the previous colour for anything else and say why', () => {
    const { state, notices } = coerceState(schema, { tint: 'red' }, { tint: '#112233' });
    expect(state.tint).toBe('#112233');
    expect(notices[0]).toMatch(/Tint: "red" is not a colour/);
  });
});

describe('samples and text fields (the measured NDF slice handed to ndf-explorer)', () => {
  const schema = {
    s: { type: 'samples', length: 4, min: 0, max: 1, default: [], label: 'Slice' },
    t: { type: 'text', maxLength: 12, default: '', label: 'Name' },
  };
  const good = { s: [1, 0.5, 1e-3, 0], t: 'gold-metallic' };
  it('take exactly `length` decimals in range or none, and a short plain name; both round-trip through the URL', () => {
    const { state, notices } = coerceState(schema, { s: '1,.5,1e-3,-0', t: 'gold (2).bin' });
    expect(notices).toEqual([]);
    expect(state.s).toEqual([1, 0.5, 0.001, 0]);
    expect(Object.is(state.s[3], 0)).toBe(true);
    expect(coerceState(schema, paramsToObject(stateToParams(schema, state).toString())).state).toEqual(state);
    expect(coerceState(schema, { s: '' }, { s: [1, 1, 1, 1], t: '' }).state.s).toEqual([]);
  });
  it('refuse a list of the wrong length, with a bad or out-of-range item, or not a list, whole, and say why', () => {
    const cases = [
      ['1,1,1', /3 values, not 4/],
      ['1,1,1,1,1', /5 values, not 4/],
      ['1,NaN,1,1', /value 2, "NaN", is not a decimal/],
      ['1,1,2,1', /value 3, "2", is not a decimal in 0…1/],
      [[1, 1, null, 1], /value 3, null/],
      ['0x1,1,1,1', /value 1/],
      [7, /7 is not a list/],
      ['__proto__', /1 values, not 4/],
    ];
    for (const [raw, why] of cases) {
      const { state, notices } = coerceState(schema, { s: raw }, { ...good, s: [1, 1, 1, 1] });
      expect(state.s, String(raw)).toEqual([1, 1, 1, 1]);
      expect(notices[0]).toMatch(why);
    }
  });
  it('refuse markup, URL schemes, control characters and long names, keeping the last name', () => {
    for (const raw of ['<b>x</b>', 'javascript:x', 'a\u0000b', '\u202eab', 'x'.repeat(13), 12, null]) {
      const { state, notices } = coerceState(schema, { t: raw }, good);
      expect(state.t).toBe('gold-metallic');
      expect(notices[0]).toMatch(/^Name: .* is not a name of at most 12 letters/);
    }
  });
});
