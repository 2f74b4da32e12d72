// The diffuse explorer's plot data against closed forms and an independent quadrature.
import { DEG } from '../../src/math/angles.js';
import { describe, expect, it } from 'vitest';
import {
  PROFILE_XS,
  SWEEP_XS,
  TRADE_XS,
  cosPhiDiff,
  diffuseAlbedo,
  lightSweep,
  profile,
  tradeOff,
} from '../../src/widgets/diffuse-explorer/model.js';
import { diffuseOrenNayar } from '../../src/math/diffuse.js';
import { fresnelSchlick } from '../../src/math/fresnel.js';
import { hemisphereIntegral } from '../../src/math/integrate.js';

const ALL = ['lambert', 'fresnelWeighted', 'ashikhminShirley', 'orenNayar', 'orenNayarQualitative'];
const state = (over = {}) => ({
  diffuse: ALL,
  sigma: 40,
  cdiff: 0.8,
  f0: 0.04,
  lightTheta: 0,
  lightPhi: 0,
  viewTheta: 45,
  ...over,
});
const params = { cdiff: 0.8, f0: 0.04, sigma: 0.6 };

describe('cosPhiDiff', () => {
  it('is the cosine of the angle between the tangent-plane projections of l and v', () => {
    const n = [0, 0, 1];
    expect(cosPhiDiff(n, [Math.SQRT1_2, 0, Math.SQRT1_2], [0.6, 0, 0.8])).toBeCloseTo(1, 14);
    expect(cosPhiDiff(n, [-0.6, 0, 0.8], [0.6, 0, 0.8])).toBeCloseTo(-1, 14);
    expect(cosPhiDiff(n, [0, 0.6, 0.8], [0.6, 0, 0.8])).toBeCloseTo(0, 14);
    // a tilted normal: rotate all three about y by 30°, the azimuth does not change
    const r = (a) => [a[0] * Math.cos(0.5) + a[2] * Math.sin(0.5), a[1], -a[0] * Math.sin(0.5) + a[2] * Math.cos(0.5)];
    const [l, v] = [
      [0.48, 0.36, 0.8],
      [0.6, 0, 0.8],
    ];
    expect(cosPhiDiff(r(n), r(l), r(v))).toBeCloseTo(cosPhiDiff(n, l, v), 12);
    expect(cosPhiDiff(n, n, [0.6, 0, 0.8])).toBe(1); // l along n: undefined, 1 by convention
  });
});

describe('diffuse albedo', () => {
  it('is c_diff for Lambert and for Oren–Nayar at sigma = 0', () => {
    expect(diffuseAlbedo('lambert', 0.5, params)).toBeCloseTo(0.8, 12);
    expect(diffuseAlbedo('orenNayar', 0.3, { ...params, sigma: 0 })).toBeCloseTo(0.8, 12);
  });
  it('matches the closed form of Fresnel-weighted Lambert: c (1 - F(nv)) (1 - f0) 20/21', () => {
    // ∫ 2mu (1 - mu)^5 dmu = 1/21 for Schlick's (1 - mu)^5
    for (const nv of [0.2, 0.7, 1]) {
      const exact = 0.8 * (1 - fresnelSchlick(0.04, nv)) * (1 - 0.04) * (20 / 21);
      expect(diffuseAlbedo('fresnelWeighted', nv, params, 512)).toBeCloseTo(exact, 6);
    }
  });
  it('for Oren–Nayar, agrees with a quadrature over the whole hemisphere of directions', () => {
    for (const nv of [0.9, 0.4]) {
      const v = [Math.sqrt(1 - nv * nv), 0, nv];
      const direct = hemisphereIntegral((l) => diffuseOrenNayar(l[2], nv, cosPhiDiff([0, 0, 1], l, v), 0.6, 0.8), 128);
      expect(diffuseAlbedo('orenNayar', nv, params, 128)).toBeCloseTo(direct, 4);
    }
  });
});

describe('plot data', () => {
  it('profile with the light at the viewer: Lambert is c·sqrt(1 - s²), Oren–Nayar flatter', () => {
    const [lambert, , , on] = profile(state(), [0, 0, 1]);
    PROFILE_XS.forEach((s, i) => expect(lambert[i]).toBeCloseTo(0.8 * Math.sqrt(Math.max(1 - s * s, 0)), 12));
    const centre = PROFILE_XS.indexOf(0);
    expect(on[centre]).toBeCloseTo(Math.PI * diffuseOrenNayar(1, 1, 1, 40 * DEG, 0.8), 12);
    const rim = PROFILE_XS.findIndex((x) => Math.abs(x - 0.9) < 1e-9);
    expect(on[rim] / on[centre]).toBeGreaterThan(lambert[rim] / lambert[centre] + 0.3);
  });
  it(
    'light sweep: Lambert is c cos(theta_l); ' + 'Oren–Nayar sends more back towards the light than to the mirror side',
    () => {
      const [lambert, , , on] = lightSweep(state());
      SWEEP_XS.forEach((deg, i) => expect(lambert[i]).toBeCloseTo(0.8 * Math.max(Math.cos(deg * DEG), 0), 12));
      const retro = SWEEP_XS.indexOf(45);
      const mirror = SWEEP_XS.indexOf(-45);
      expect(on[retro]).toBeGreaterThan(1.3 * on[mirror]);
    },
  );
  it('trade-off: Lambert under a specular term makes energy at grazing; the weighted forms do not', () => {
    const { specular, totals } = tradeOff(state({ cdiff: 1 }));
    TRADE_XS.forEach((deg, i) => expect(specular[i]).toBeCloseTo(fresnelSchlick(0.04, Math.cos(deg * DEG)), 14));
    expect(totals[0].at(-1)).toBeGreaterThan(1.5);
    expect(Math.max(...totals[1])).toBeLessThanOrEqual(1);
    expect(Math.max(...totals[2])).toBeLessThanOrEqual(1);
  });
});
