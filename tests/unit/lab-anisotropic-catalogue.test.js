// The anisotropic D and V that the material lab, the BRDF lobe and the NDF explorer stretch come from the term
// catalogue (src/math/catalogue/anisotropic-forms.js): the lab's GLSL calls are the catalogue dispatch's own calls
// (termCall), the user's anisotropic D and V are the slots' calls (src/core/custom/slots.js), and an anisotropic
// entry added to the catalogue is stretched by all three with no edit of theirs.
import { afterEach, describe, expect, it } from 'vitest';
import { CATALOGUE } from '../../src/math/catalogue/index.js';
import { anisotropicForm } from '../../src/math/catalogue/anisotropic-forms.js';
import { termCall } from '../../src/core/gpu/term-chunks.js';
import { SLOTS } from '../../src/core/custom/slots.js';
import { anisotropicDefines, anisotropyOf, ownSlots } from '../../src/lab/lab-anisotropy.js';
import { sceneDefines } from '../../src/lab/lab-defines.js';
import { labScene } from '../../src/lab/lab-scene.js';
import { approximationNotes } from '../../src/lab/lab-approximations.js';
import { schema } from '../../src/widgets/material-lab/schema.js';
import { lightsOf } from '../../src/widgets/material-lab/model.js';
import { FORMULA } from '../../src/widgets/material-lab/words.js';
import { anisotropyOf as lobeAnisotropyOf } from '../../src/widgets/brdf-lobe/model.js';
import { anisotropicLobe } from '../../src/widgets/ndf-explorer/model.js';
import { ndfGGXAniso } from '../../src/math/anisotropic.js';

const defaults = Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default]));
const stateWith = (patch) => ({ ...defaults, anisotropy: 0.6, ...patch });
const sceneOf = (patch) => labScene(stateWith(patch), lightsOf(stateWith(patch)));
const { ndf, visibility } = CATALOGUE;

afterEach(() => {
  delete ndf.terms.blinnPhongAniso;
});

describe('the stretched lobe’s terms, from the catalogue', () => {
  it('each anisotropic entry names the isotropic term of its family it stretches', () => {
    expect(anisotropicForm('ndf', 'ggx')).toBe(ndf.terms.ggxAniso);
    expect(anisotropicForm('ndf', 'beckmann')).toBe(ndf.terms.beckmannAniso);
    expect(anisotropicForm('visibility', 'smithGGXCorrelated')).toBe(visibility.terms.smithGGXCorrelatedAniso);
    expect(anisotropicForm('ndf', 'sgd')).toBeNull();
    expect(anisotropicForm('visibility', 'kelemen')).toBeNull();
    for (const family of [ndf, visibility])
      for (const term of Object.values(family.terms).filter((t) => t.isotropic))
        expect(family.terms[term.isotropic]?.evaluate, term.key).toBeTypeOf('function'); // an isotropic term
  });

  it('the lab draws the catalogue dispatch’s calls of the chosen D and V, or the slots’ calls', () => {
    const ggx = sceneDefines(sceneOf({}), false);
    expect(ggx.ANISOTROPIC_D).toBe(termCall(ndf.terms.ggxAniso));
    expect(ggx.ANISOTROPIC_V).toBe(termCall(visibility.terms.smithGGXCorrelatedAniso));
    expect(ggx.NDF_GGX).toBe(1); // the isotropic lobe the tables and the prefilter are built for
    const beckmann = sceneDefines(sceneOf({ D: 'beckmann', V: 'schlickGGX' }), true);
    expect(beckmann.ANISOTROPIC_D).toBe(termCall(ndf.terms.beckmannAniso));
    expect(beckmann).not.toHaveProperty('ANISOTROPIC_V'); // Schlick–GGX has no anisotropic form: at α
    const own = sceneDefines(sceneOf({ anisoD: 'custom', anisoV: 'custom' }), false);
    expect([own.ANISOTROPIC_D, own.ANISOTROPIC_V]).toEqual([SLOTS.DAniso.call, SLOTS.VAniso.call]);
    expect(own).toMatchObject({ CUSTOM_DANISO: 1, CUSTOM_VANISO: 1 });
    expect(ownSlots(anisotropyOf(stateWith({ anisoV: 'custom' })))).toEqual(['VAniso']);
    expect(ownSlots(anisotropyOf(stateWith({ anisotropy: 0, anisoD: 'custom' })))).toEqual([]);
  });

  it('says the user’s D is sampled by GGX’s visible normals, and names its functions', () => {
    const formula = FORMULA(stateWith({ anisoD: 'custom', anisoV: 'custom' }));
    expect(formula).toContain('\\sym{anisoD}{D_{\\text{yours}}}');
    expect(formula).toContain('\\sym{anisoV}{V_{\\text{yours}}}');
    expect(FORMULA(stateWith({}))).toContain('\\sym{D}{D_{\\text{GGX}}}');
    const notes = approximationNotes(sceneOf({ anisoD: 'custom', anisoV: 'custom' })).join(' ');
    expect(notes).toMatch(/D your customDAniso at the pair, V your customVAniso\./);
    expect(notes).toMatch(/visible normals of GGX, anisotropic at the same pair .* divided by its density/);
  });

  it('a new anisotropic entry of the catalogue is stretched by the lab, the lobe and the explorer unedited', () => {
    // Blinn–Phong has no anisotropic form; one added here (its function: GGX's, a stand-in) is picked up by all
    ndf.terms.blinnPhongAniso = { ...ndf.terms.ggxAniso, key: 'blinnPhongAniso', isotropic: 'blinnPhong' };
    const lab = anisotropicDefines({ anisotropy: anisotropyOf(stateWith({ D: 'blinnPhong' })) }, false);
    expect(lab.ANISOTROPIC_D).toBe(termCall(ndf.terms.blinnPhongAniso));
    const lobe = lobeAnisotropyOf({ anisotropy: 0.5, alpha: 0.3, convention: 'burley2012', phi: 0 }, 'blinnPhong');
    expect(lobe?.D).toBe('blinnPhongAniso');
    const explorer = anisotropicLobe('blinnPhong', { alpha: 0.3 }, { anisotropy: 0.5, convention: 'gltf' });
    expect(explorer?.key).toBe('blinnPhongAniso');
    expect(explorer?.D).toBe(ndfGGXAniso);
    // a term in a chunk the lab's program does not include is refused, not drawn as something else
    ndf.terms.blinnPhongAniso.chunk = 'elsewhere.glsl';
    expect(() => anisotropicDefines({ anisotropy: anisotropyOf(stateWith({ D: 'blinnPhong' })) }, false)).toThrow(
      /elsewhere\.glsl is not included/,
    );
  });
});
