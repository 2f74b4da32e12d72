// The BRDF lobe's free azimuths and anisotropy (issue 28): an anisotropic lobe in the plane of incidence along an
// axis is the isotropic lobe at that axis' α times
// αx/αy (or αy/αx): along an axis D is the isotropic D at that α times the ratio, and Smith's projected roughness
// is that α (Heitz 2014).
import { describe, expect, it } from 'vitest';
import { lobeScene } from '../../src/widgets/brdf-lobe/model.js';
import { anisotropicAlphas } from '../../src/math/anisotropic.js';
import { schema } from '../../src/widgets/brdf-lobe/schema.js';
import { coerceState } from '../../src/core/framework/state.js';

const defaults = Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, f.default]));
const state = (over) => ({ ...defaults, lightTheta: 40, viewTheta: 30, ...over });
const values = (s) => lobeScene(s).lobeA.map((x) => x[1]);

describe('brdf-lobe: the plane of incidence at any azimuth, A anisotropic', () => {
  it('along the tangent it is the isotropic lobe at αx times αx/αy; along the bitangent at αy times αy/αx', () => {
    const [ax, ay] = anisotropicAlphas(0.3, 0.7, 'burley2012');
    // the plane of incidence (opposite the light's azimuth) along t, then along b
    for (const [lightPhi, a, ratio] of [
      [180, ax, ax / ay],
      [270, ay, ay / ax],
    ]) {
      const aniso = values(state({ anisotropy: 0.7, lightPhi, useF: false }));
      const iso = values(state({ alpha: a, useF: false }));
      aniso.forEach((x, i) => expect(x).toBeCloseTo(iso[i] * ratio, 9));
    }
  });
  it('with a V that has no anisotropic form, V stays isotropic at α and the label says which D', () => {
    const s = state({ anisotropy: 0.5, V: 'smithGGXSeparable' });
    const scene = lobeScene(s);
    expect(scene.A.aniso).toMatchObject({ D: 'ggxAniso', V: null });
    expect(scene.A.label).toBe('A: GGX aniso. + Smith GGX, separable');
    expect(lobeScene(state({ anisotropy: 0.5, D: 'blinnPhong' })).A.aniso).toBeNull();
  });
});

describe('brdf-lobe: an old link’s plane azimuth `phi`', () => {
  it('reads as the light’s azimuth: the old scene turned by 180° about n, values D and Λ do not tell apart', () => {
    const { state: read, notices } = coerceState(schema, { phi: '60', anisotropy: '0.7', viewTheta: '-20' });
    expect(notices).toEqual([]);
    expect([read.lightPhi, read.viewPhi]).toEqual([60, 0]);
    // the old scene: the plane's mirror side at 60°, the light at 240° (lightPhi 240 is that scene exactly)
    const old = values({ ...read, lightTheta: 40, lightPhi: 240 });
    const turned = values({ ...read, lightTheta: 40 });
    turned.forEach((x, i) => expect(x).toBeCloseTo(old[i], 12));
    expect(Math.max(...turned)).toBeGreaterThan(0);
  });
});
