// The white furnace of OpenPBR's non-absorbing stacks: every colour 1, the directional albedo ∫ f (n·l) dω of
// openPbrBRDF by quadrature (tests/support/openpbr-albedo.js: each layer over its half vector or over directions,
// converged to 1e-4), at most 1 at every angle, and what each stack loses, printed. What is lost is the single
// scattering of the microfacet lobes (the talk's model: metals lose what Heitz et al. 2016's walk puts back); the
// albedo scaling itself keeps E_layer = E_top + (1 − E_top) E_below, so a white base under a dielectric loses nothing
// but the table's interpolation error (up to 1.2e-3, openpbr-albedo.test.js), which is the tolerance above 1.
import { describe, expect, it } from 'vitest';
import { openPbrAlbedo } from '../support/openpbr-albedo.js';
import { albedoGGX } from '../../src/math/integrate.js';

const WHITE = { base_color: 1, specular_color: 1, coat_color: 1, fuzz_color: 1 };
const STACKS = {
  'glossy diffuse': { ...WHITE },
  'rough glossy diffuse': { ...WHITE, specular_roughness: 1, base_diffuse_roughness: 1 },
  metal: { ...WHITE, base_metalness: 1 },
  'coat over glossy diffuse': { ...WHITE, coat_weight: 1, coat_roughness: 0.2 },
  'rough coat over metal': { ...WHITE, coat_weight: 1, base_metalness: 1, coat_roughness: 0.5 },
  'fuzz, half coat, half metal': {
    ...WHITE,
    fuzz_weight: 1,
    coat_weight: 0.5,
    base_metalness: 0.5,
    coat_roughness: 0.3,
  },
};
const MUS = [1, 0.5, 0.2, 0.05, 0.01];
const TABLE_ERROR = 1.5e-3;
const N = 24; // nodes per axis of each piece: 24 against 48 differ by < 1e-4 (the first test)

describe('the white furnace of every non-absorbing stack', () => {
  it('the quadrature has converged: 24 and 48 nodes agree within 1e-4', () => {
    for (const mu of [1, 0.05]) {
      const [a, b] = [24, 48].map((n) => openPbrAlbedo(STACKS['fuzz, half coat, half metal'], mu, n).total[0]);
      expect(Math.abs(a - b)).toBeLessThan(1e-4);
    }
  });
  const lines = [];
  for (const [name, material] of Object.entries(STACKS)) {
    it(`${name}: ∫ f cos ≤ 1 at every angle`, () => {
      const E = MUS.map((mu) => openPbrAlbedo(material, mu, N).total[0]);
      E.forEach((e) => expect(e).toBeLessThanOrEqual(1 + TABLE_ERROR));
      lines.push(`${name.padEnd(30)} ${E.map((e) => (1 - e).toFixed(4).padStart(8)).join(' ')}`);
      if (name === 'metal') {
        // a white metal is GGX with F = 1: its albedo is the split sum's (integrate.js), computed apart
        MUS.forEach((mu, i) => expect(E[i]).toBeCloseTo(albedoGGX(mu, 0.09), 4));
      }
    });
  }
  it('prints what each loses, 1 − E at n·v = ' + MUS.join(', '), () => {
    console.log(lines.join('\n'));
    expect(lines).toHaveLength(Object.keys(STACKS).length);
  });
});
