// The 3-D microsurface (src/math/heightfield.js): a Gaussian random heightfield's facets have the slope variances
// asked for (Beckmann's αx, αy), rays cast against it find what an independent brute force finds, and its
// ray-traced G1 agrees with Smith's closed form for anisotropic Beckmann, smithG1BeckmannAniso, at several azimuths.
import { describe, expect, it } from 'vitest';
import { seededRandom } from '../../src/math/microsurface.js';
import { smithG1BeckmannAniso } from '../../src/math/anisotropic.js';
import {
  blocked,
  cellMaxima,
  facetAlphas,
  generateHeightfield,
  measuredG1Aniso,
  surfaceAt,
} from '../../src/math/heightfield.js';

const DEG = Math.PI / 180;
const dir = (t, p) => [Math.sin(t * DEG) * Math.cos(p * DEG), Math.sin(t * DEG) * Math.sin(p * DEG), Math.cos(t * DEG)];
const field = generateHeightfield(256, 0.6, 0.2, { seed: 3 });
const maxima = cellMaxima(field);
const alphas = facetAlphas(field);

describe('generateHeightfield: a Gaussian surface with Beckmann slopes', () => {
  it('its facets’ roughness pair is the one asked for within 10% (the lattice and 400 waves)', () => {
    expect(alphas[0] / 0.6).toBeGreaterThan(0.9);
    expect(alphas[0] / 0.6).toBeLessThan(1.1);
    expect(alphas[1] / 0.2).toBeGreaterThan(0.9);
    expect(alphas[1] / 0.2).toBeLessThan(1.1);
  });
  it('is periodic: the height wraps round at the grid’s edge', () => {
    expect(surfaceAt(field, 256.25, 3.5).z).toBeCloseTo(surfaceAt(field, 0.25, 3.5).z, 12);
  });
});

describe('blocked: the grid walk against a brute-force march along the ray', () => {
  it('agrees with sampling the ray every 0.01 cells on 400 random rays', () => {
    const rand = seededRandom(11);
    let [disagree, hits] = [0, 0];
    for (let r = 0; r < 400; r++) {
      const [x, y] = [rand() * 256, rand() * 256];
      const w = dir(50 + 35 * rand(), 360 * rand());
      const p = [x, y, surfaceAt(field, x, y).z + 1e-9];
      let brute = false;
      for (let s = 0.02; p[2] + s * w[2] <= maxima.top && !brute; s += 0.01) {
        brute = p[2] + s * w[2] < surfaceAt(field, p[0] + s * w[0], p[1] + s * w[1]).z;
      }
      hits += brute ? 1 : 0;
      if (blocked(field, maxima, p, w) !== brute) disagree++;
    }
    expect(hits).toBeGreaterThan(40); // the rays test something
    expect(disagree).toBeLessThanOrEqual(2); // a march at 0.01 can step over a graze the exact walk sees
  });
});

describe('measuredG1Aniso: ray-traced G1 against Smith’s anisotropic Beckmann G1 (closed form)', () => {
  // Smith's G1 for the surface's own (αx, αy); averaged over all facets facing the light the two must agree up to
  // sampling (a heightfield shows the light exactly its footprint, and Smith keeps the same balance): 60 000 rays
  // give a standard error ~0.002, and the tolerance 0.012 leaves room for slopes a sum of 400 waves makes only
  // nearly Beckmann's (along t and b they correlate by ~0.05, which the pair (αx, αy) cannot say)
  const cases = [60, 75, 85].flatMap((theta) => [0, 30, 60, 90, 135].map((phi) => [theta, phi]));
  it.each(cases)('θ = %i°, φ = %i°: within 0.012', (theta, phi) => {
    const w = dir(theta, phi);
    const got = measuredG1Aniso(field, maxima, w, { samples: 60000, seed: theta * 1000 + phi });
    expect(Math.abs(got.g1 - smithG1BeckmannAniso(...w, ...alphas))).toBeLessThan(0.012);
  });
  it('falls with the projected roughness: lower along t (αx = 0.6) than along b (αy = 0.2) at θ = 80°', () => {
    const [alongT, alongB] = [0, 90].map((p) => measuredG1Aniso(field, maxima, dir(80, p), { samples: 20000 }).g1);
    expect(alongB - alongT).toBeGreaterThan(0.2);
  });
  it('departs from Smith per facet: those tilted away from the light are shadowed more than those towards it', () => {
    const got = measuredG1Aniso(field, maxima, dir(75, 0), { samples: 40000 });
    expect(got.towards - got.away).toBeGreaterThan(0.05);
  });
});
