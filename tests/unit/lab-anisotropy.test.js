// The material lab's anisotropic lobe in Node (src/lab/lab-anisotropy.js and the paths that read it): the pair
// against the closed forms of Burley 2012 (aspect √(1 − 0.9a)) and KHR_materials_anisotropy (mix(α, 1, a²)); which
// programs stretch the lobe; the uniforms bound by the parameters table (issue 27), each against the value it carries.
import { describe, expect, it } from 'vitest';
import { anisotropyOf, stretchesLobe, tangentFieldOf } from '../../src/lab/lab-anisotropy.js';
import { sceneDefines } from '../../src/lab/lab-defines.js';
import { createLabUniforms, setSceneUniforms } from '../../src/lab/lab-uniforms.js';
import { approximationNotes } from '../../src/lab/lab-approximations.js';
import { labScene } from '../../src/lab/lab-scene.js';
import { schema } from '../../src/widgets/material-lab/schema.js';
import { BRUSHED_ALUMINIUM, lightsOf } from '../../src/widgets/material-lab/model.js';

const defaults = Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default]));
const stateWith = (patch) => ({ ...defaults, ...patch });
const sceneOf = (patch) => labScene(stateWith(patch), lightsOf(stateWith(patch)));
const MAPS = { env: null, irradiance: null, prefiltered: () => null, sampling: { usable: false } };

describe('the lab’s anisotropic lobe', () => {
  it('is off at a = 0, and its pair is Burley’s (α/√(1 − 0.9a), α√(1 − 0.9a)) or glTF’s (mix(α, 1, a²), α)', () => {
    expect(anisotropyOf(stateWith({ anisotropy: 0 }))).toBeNull();
    expect(anisotropyOf({ alpha: 0.3 })).toBeNull(); // the lab's other widgets have no anisotropy
    const burley = anisotropyOf(stateWith({ alpha: 0.25, anisotropy: 0.8 }));
    const aspect = Math.sqrt(1 - 0.72);
    expect(burley.alpha[0]).toBeCloseTo(0.25 / aspect, 14);
    expect(burley.alpha[1]).toBeCloseTo(0.25 * aspect, 14);
    const gltf = anisotropyOf(stateWith({ alpha: 0.25, anisotropy: 0.5, anisotropyModel: 'gltf' }));
    expect(gltf.alpha).toEqual([0.25 + 0.75 * 0.25, 0.25]);
  });

  it('lays the field along the pole of (θ, φ) from the view, as the lights’ angles are', () => {
    const f = tangentFieldOf(stateWith({ tangentTheta: 90, tangentPhi: 90, tangentRotation: 30 }));
    expect(f.axis.map((x) => Math.round(x * 1e12) / 1e12)).toEqual([0, 1, 0]); // up, in the picture's plane
    expect(f.rotation).toBeCloseTo(Math.PI / 6, 14);
    expect(tangentFieldOf(stateWith({ tangentField: 'along' })).mode).toBe('along');
  });

  it('stretches a D with an anisotropic form, with the specular layer on, and not a measured table', () => {
    const on = { anisotropy: 0.5 };
    expect(stretchesLobe(sceneOf(on))).toBe(true);
    expect(stretchesLobe(sceneOf({ ...on, D: 'beckmann' }))).toBe(true);
    expect(stretchesLobe(sceneOf({ ...on, layers: 'diffuse' }))).toBe(false);
    expect(stretchesLobe({ ...sceneOf(on), measured: 'a table' })).toBe(false);
    expect(sceneDefines(sceneOf(on), false)).toMatchObject({ ANISOTROPIC: 1, BENT_REFLECTION: 1 });
    expect(sceneDefines(sceneOf(on), true)).not.toHaveProperty('BENT_REFLECTION'); // the reference has no shortcut
    expect(sceneDefines(sceneOf({ ...on, tangentField: 'along' }), true)).toMatchObject({ TANGENT_ALONG: 1 });
    expect(sceneDefines(sceneOf({ ...on, bentReflection: false }), false)).not.toHaveProperty('BENT_REFLECTION');
    expect(sceneDefines(sceneOf({}), false)).not.toHaveProperty('ANISOTROPIC');
    const beckmann = approximationNotes(sceneOf({ ...on, D: 'beckmann' })).join(' ');
    expect(beckmann).toMatch(/D Beckmann, anisotropic at the pair.*visible normals of GGX, anisotropic at the same/);
  });

  it('feeds the uniforms through the parameters table: α, the pair, a, F0, c_diff, σ and a term’s own', () => {
    const uniforms = createLabUniforms(8);
    const scene = { ...sceneOf(BRUSHED_ALUMINIUM), maps: MAPS };
    setSceneUniforms(uniforms, scene, { reference: true, dfg: () => null });
    const [ax, ay] = scene.anisotropy.alpha;
    expect([uniforms.uAlpha.value, uniforms.uAlphaPair.value]).toEqual([0.25, [ax, ay]]);
    expect(uniforms.uAnisotropy.value).toBe(0.8);
    expect(uniforms.uF0.value).toEqual(scene.material.f0);
    expect(uniforms.uDiffuse.value).toEqual([0, 0, 0]); // a metal
    expect(uniforms.uTangentAxis.value).toEqual(scene.anisotropy.field.axis);
    // isotropic: the pair is α twice, a is 0; Blinn–Phong's exponent from its entry's default
    const iso = { ...sceneOf({ alpha: 0.4, sigma: 30, D: 'ggx' }), maps: MAPS };
    setSceneUniforms(uniforms, iso, { reference: true, dfg: () => null });
    expect([uniforms.uAlphaPair.value, uniforms.uAnisotropy.value]).toEqual([[0.4, 0.4], 0]);
    expect(uniforms.uSigma.value).toBeCloseTo((30 * Math.PI) / 180, 14);
    expect(uniforms.uDiffuse.value).toEqual(iso.material.diffuse);
    expect(uniforms.uExponent.value).toBe(40);
  });
});
