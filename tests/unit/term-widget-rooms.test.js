// The widgets that list BRDF terms (ndf-explorer, visibility-explorer, diffuse-explorer, brdf-lobe, energy), room
// by room: their schema, model and words load in Node with three.js, lil-gui and uPlot refused; every term menu
// is the catalogue's (its keys and its one label per term); and every sphere variant a term menu can ask for is
// one that shader assembly accepts (assembleGlsl refuses a define no chunk reads and a term chain without a match).
import { describe, expect, it, vi } from 'vitest';
import { CATALOGUE, termOptions } from '../../src/math/catalogue/index.js';
import { assembleGlsl } from '../../src/core/gpu/glsl.js';
import { SHADER_CHUNKS } from '../../src/core/gpu/shader-chunks.js';

const WIDGETS = ['ndf-explorer', 'visibility-explorer', 'diffuse-explorer', 'brdf-lobe', 'energy'];
const ROOMS = ['schema', 'model', 'words'];

describe('schema, model and words load without three.js, lil-gui or uPlot', () => {
  it.each(WIDGETS.flatMap((w) => ROOMS.map((room) => [w, room])))('%s/%s.js', async (w, room) => {
    vi.resetModules();
    for (const name of ['three', 'lil-gui', 'uplot'])
      vi.doMock(name, () => {
        throw new Error(`${w}/${room}.js loads ${name}`);
      });
    await expect(import(`../../src/widgets/${w}/${room}.js`)).resolves.toBeTruthy();
    for (const name of ['three', 'lil-gui', 'uplot']) vi.doUnmock(name);
  });
});

describe('every term menu is the catalogue’s: its keys and labels', () => {
  const menus = async () => {
    const schema = async (w) => (await import(`../../src/widgets/${w}/schema.js`)).schema;
    const [ndf, vis, diffuse, lobe, energy] = await Promise.all(WIDGETS.map(schema));
    return [
      ['ndf-explorer NDFs', ndf.D, 'ndf', 'the talk’s five, whose widths it matches'],
      ['visibility-explorer terms', vis.V, 'visibility'],
      ['diffuse-explorer models', diffuse.diffuse, 'diffuse'],
      ['brdf-lobe A: D', lobe.D, 'ndf'],
      ['brdf-lobe B: D', lobe.D2, 'ndf'],
      ['brdf-lobe A: V', lobe.V, 'visibility'],
      ['brdf-lobe B: V', lobe.V2, 'visibility'],
      ['brdf-lobe F', lobe.F, 'fresnel', 'Schlick and F = 1'],
      ['energy compensation', energy.compensation, 'compensation'],
    ];
  };
  it('each option’s label is the catalogue’s label of its key; a family offered whole unless said', async () => {
    for (const [name, field, family, subset] of await menus()) {
      const { custom, ...options } = field.options; // `custom`: the user's own GLSL (issue 13), no catalogue term
      if (custom) expect(name, 'custom terms: brdf-lobe’s A and the explorers').toMatch(/^brdf-lobe [AF]|-explorer/);
      const keys = Object.keys(options);
      expect(options, name).toEqual(termOptions(family, keys));
      // whole: every term with a curve of the cosines (an anisotropic lobe comes by a view's anisotropy control)
      const whole = Object.values(CATALOGUE[family].terms).filter(
        (t) => t.evaluate || !CATALOGUE[family].microfacetInput,
      );
      if (!subset) expect(keys.toSorted(), name).toEqual(whole.map((t) => t.key).toSorted());
    }
  });
});

describe('every sphere variant a term menu can ask for assembles', () => {
  const load = async (w) => import(`../../src/widgets/${w}/spheres.js`);
  const assemble = (defines) => assembleGlsl(SHADER_CHUNKS['brdf-sphere.frag.glsl'], { defines });
  const keys = (family) => Object.keys(CATALOGUE[family].terms);
  const state = { lightTheta: 30, lightPhi: 0, exposure: 1, alpha: 0.5, cdiff: 0.8, f0: 0.04, sigma: 20 };

  it('ndf-explorer: one sphere per NDF of the catalogue (F = 1, V = 1)', async () => {
    const { sphereCell } = await load('ndf-explorer');
    for (const key of keys('ndf')) expect(() => assemble(sphereCell({ key, p: {} }, state).defines), key).not.toThrow();
  });
  it('visibility-explorer: one sphere per visibility term of the catalogue (GGX D, F = 1)', async () => {
    const { sphereCell } = await load('visibility-explorer');
    for (const key of keys('visibility')) expect(() => assemble(sphereCell({ key }, state).defines), key).not.toThrow();
  });
  it('diffuse-explorer: one sphere per diffuse term of the catalogue, specular off', async () => {
    const { sphereCell } = await load('diffuse-explorer');
    for (const key of keys('diffuse'))
      expect(() => assemble(sphereCell(key, state, [0, 0, 1]).defines), key).not.toThrow();
  });
  it('energy: the furnace with each compensation of the catalogue', async () => {
    const { furnaceDefines } = await load('energy');
    for (const key of keys('compensation')) expect(() => assemble(furnaceDefines(key)), key).not.toThrow();
  });
  it('and a define the sphere shader does not read is refused (the check can fail)', () => {
    expect(() => assemble({ FURNACE: 1, FURNACE_KULLA_CONTY: 1 })).toThrow(/FURNACE_KULLA_CONTY/);
  });
});
