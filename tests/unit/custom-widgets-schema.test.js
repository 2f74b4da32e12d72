// The user's own term in the schemas of ndf-explorer, visibility-explorer, diffuse-explorer and the material lab
// (issue 13): `custom` in each menu, the code field of the right slot (its default the slot's starter), the code
// and the sliders' values through the URL and back, code past the size limit refused with a notice; and the lab's
// scene for the user's BRDF: the whole-BRDF path, sampled by GGX at the state's α, the reference restarted when the
// code or a slider changes.
import { describe, expect, it } from 'vitest';
import { coerceState, defaultState, paramsToObject, stateToParams } from '../../src/core/framework/state.js';
import { MAX_CODE_CHARS } from '../../src/core/custom/code-state.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { schema as ndf } from '../../src/widgets/ndf-explorer/schema.js';
import { schema as visibility } from '../../src/widgets/visibility-explorer/schema.js';
import { schema as diffuse } from '../../src/widgets/diffuse-explorer/schema.js';
import { schema as lab } from '../../src/widgets/material-lab/schema.js';
import { sceneOf } from '../../src/widgets/material-lab/model.js';
import { sceneDefines } from '../../src/lab/lab-defines.js';

const WIDGETS = [
  { name: 'ndf-explorer', schema: ndf, menu: 'D', codeKey: 'codeD', slot: 'D' },
  { name: 'visibility-explorer', schema: visibility, menu: 'V', codeKey: 'codeV', slot: 'V' },
  { name: 'diffuse-explorer', schema: diffuse, menu: 'diffuse', codeKey: 'codeDiffuse', slot: 'diffuse' },
  { name: 'material-lab', schema: lab, menu: 'brdfSource', codeKey: 'codeBRDF', slot: 'brdf' },
];
const CODE = 'float x; // a long line to make lz-string worth it '.repeat(40);

describe.each(WIDGETS)('$name: the user’s term in the state', ({ schema, menu, codeKey, slot }) => {
  it('offers custom in its menu, the slot’s starter as the code’s default, no custom term drawn by default', () => {
    expect(schema[menu].options).toHaveProperty('custom');
    expect(schema[codeKey]).toMatchObject({ type: 'code', slot, default: SLOTS[slot].starter });
    const state = defaultState(schema);
    expect([state[menu]].flat()).not.toContain('custom');
    expect(state.params).toEqual({});
  });

  it('carries the code and the sliders’ values through the URL and back', () => {
    const { state } = coerceState(schema, { [codeKey]: CODE, params: { gain: 0.25, width: 3 } });
    const url = stateToParams(schema, state).toString();
    expect(url.length).toBeLessThan(CODE.length); // compressed
    const back = coerceState(schema, paramsToObject(url));
    expect(back.state[codeKey]).toBe(CODE);
    expect(back.state.params).toEqual({ gain: 0.25, width: 3 });
    expect(back.notices).toEqual([]);
  });

  it('refuses code past the size limit with a notice and keeps the code it had', () => {
    const { state, notices } = coerceState(schema, { [codeKey]: 'x'.repeat(MAX_CODE_CHARS + 1) });
    expect(state[codeKey]).toBe(SLOTS[slot].starter);
    expect(notices.join(' ')).toMatch(/at most 8000/);
  });
});

describe('material lab: the scene of the user’s BRDF', () => {
  const state = { ...defaultState(lab), brdfSource: 'custom', alpha: 0.004, punctual: true };
  const custom = { code: SLOTS.brdf.starter, params: { albedo: 0.5 } };

  it('is a whole BRDF (the MEASURED path, no model terms) sampled by GGX at the state’s α, at least 0.01', () => {
    const { scene } = sceneOf(state, null, 'studio', custom);
    expect(scene.custom).toEqual(custom);
    expect(scene.material.alpha).toBe(0.01);
    expect(sceneDefines(scene, true)).toMatchObject({ MEASURED: 1, REFERENCE: 1, NDF_GGX: 1, LIGHT_PUNCTUAL: 1 });
    expect(sceneDefines(scene, false)).not.toHaveProperty('F_SCHLICK');
  });

  it('starts the reference over when the code or a slider changes, not when the exposure does', () => {
    const keys = (s, c) => sceneOf(s, null, 'studio', c).keys.reference;
    const base = keys(state, custom);
    expect(keys(state, { ...custom, params: { albedo: 0.6 } })).not.toBe(base);
    expect(keys(state, { ...custom, code: `${custom.code}\n` })).not.toBe(base);
    expect(keys({ ...state, exposure: 2 }, custom)).toBe(base);
  });
});
