// The irradiance map against closed forms: a uniform environment gives its radiance everywhere; a sky that is
// 1 above the horizon and 0 below gives (1 + n_y)/2 (the cosine-weighted share of the sky seen by n).
import { describe, expect, it } from 'vitest';
import { irradianceMap } from '../../src/lab/env-irradiance.js';
import { equirectDirection } from '../../src/math/lighting.js';

const W = 128;
const H = 64;
const map = (radiance) => {
  const data = new Float32Array(W * H * 4);
  for (let j = 0; j < H; j++)
    for (let i = 0; i < W; i++)
      data.set([...radiance(equirectDirection((i + 0.5) / W, (j + 0.5) / H)), 1], (j * W + i) * 4);
  return data;
};

describe('irradiance map', () => {
  it('of a uniform environment is its radiance, for every normal', () => {
    const out = irradianceMap(
      map(() => [2, 1, 0.5]),
      W,
      H,
      8,
      4,
    );
    for (let t = 0; t < 32; t++) {
      expect(out[4 * t]).toBeCloseTo(2, 2);
      expect(out[4 * t + 1]).toBeCloseTo(1, 2);
      expect(out[4 * t + 2]).toBeCloseTo(0.5, 2);
    }
  });
  it('of a bright sky over a black ground is (1 + n_y)/2', () => {
    const out = irradianceMap(
      map((d) => (d[1] > 0 ? [1, 1, 1] : [0, 0, 0])),
      W,
      H,
      8,
      8,
    );
    for (let q = 0; q < 8; q++) {
      const ny = equirectDirection(0.5, (q + 0.5) / 8)[1];
      expect(out[(q * 8 + 3) * 4]).toBeCloseTo((1 + ny) / 2, 2);
    }
  });
});
