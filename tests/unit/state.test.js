import { describe, expect, it } from 'vitest';
import { coerceState, defaultState, paramsToObject, stateToParams } from '../../src/core/state.js';
import { schema as zonesSchema } from '../../src/widgets/fresnel-zones/fresnel-zones.js';
import { schema as curvesSchema } from '../../src/widgets/fresnel-curves/fresnel-curves.js';

describe('widget state', () => {
  it('round-trips through URL parameters', () => {
    for (const schema of [zonesSchema, curvesSchema]) {
      const { state } = coerceState(schema, { mode: 'zones-lh', lightTheta: 123.4, materials: ['gold', 'water'], schlick: false });
      const back = coerceState(schema, paramsToObject(stateToParams(schema, state).toString())).state;
      expect(back).toEqual(state);
    }
  });
  it('clamps numbers, keeps the previous value for bad ones, ignores unknown keys, and reports each', () => {
    const base = defaultState(zonesSchema);
    const { state, notices } = coerceState(zonesSchema, { lightTheta: '400', alpha: 'x', mode: 'banana', nonsense: '1' }, base);
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
