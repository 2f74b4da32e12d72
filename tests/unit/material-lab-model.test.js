// The material lab's schema, model and defines in Node (no three.js, no DOM): old links' diffuse spellings, the
// scene a state makes, and the defines of the program that draws it, against the catalogue's own entries.
import { describe, expect, it } from 'vitest';
import { coerceState, defaultState } from '../../src/core/framework/state.js';
import { schema } from '../../src/widgets/material-lab/schema.js';
import { missingFile, sceneOf } from '../../src/widgets/material-lab/model.js';
import { sceneDefines } from '../../src/lab/lab-defines.js';
import { CATALOGUE, TERM_ALIASES } from '../../src/math/catalogue/index.js';

const OLD_DIFFUSE = ['fresnel-weighted', 'ashikhmin-shirley', 'oren-nayar', 'oren-nayar-qualitative'];

describe('material lab: schema and model', () => {
  it('reads every old diffuse spelling as the catalogue key TERM_ALIASES names, without a notice', () => {
    for (const old of OLD_DIFFUSE) {
      const { state, notices } = coerceState(schema, { diffuse: old });
      expect(state.diffuse).toBe(TERM_ALIASES.diffuse[old]);
      expect(CATALOGUE.diffuse.terms[state.diffuse].key).toBe(state.diffuse);
      expect(notices).toEqual([]);
    }
  });
  it('gives each program one define of each term family, the catalogue entry’s (no silent GGX default)', () => {
    const state = { ...defaultState(schema), diffuse: 'orenNayar', D: 'beckmann', V: 'kelemen' };
    const { scene } = sceneOf(state, null, 'studio');
    for (const reference of [false, true]) {
      const defines = sceneDefines(scene, reference);
      const of = (family) => Object.keys(defines).filter((d) => d.startsWith(`${CATALOGUE[family].definePrefix}_`));
      expect(of('ndf')).toEqual([CATALOGUE.ndf.terms.beckmann.define]);
      expect(of('visibility')).toEqual([CATALOGUE.visibility.terms.kelemen.define]);
      expect(of('fresnel')).toEqual([CATALOGUE.fresnel.terms.schlick.define]);
      expect(of('diffuse')).toEqual([CATALOGUE.diffuse.terms.orenNayar.define]);
    }
  });
  it('keeps the model (or the studio) with a notice when the measured table (or the file) is not there yet', () => {
    const state = { ...defaultState(schema), brdfSource: 'measured', environment: 'file' };
    const none = { measured: false, file: false };
    expect(missingFile(['brdfSource'], state, none)).toEqual({
      notice: 'noMeasured',
      instead: { brdfSource: 'model' },
    });
    expect(missingFile(['environment'], state, none)).toEqual({ notice: 'noFile', instead: { environment: 'studio' } });
    expect(missingFile(['brdfSource', 'environment'], state, { measured: true, file: true })).toBeNull();
  });
});
