// The illumination models' math against independent integrals: the split-sum DFG table, the samplers'
// densities, and the sphere light (its c_light and its representative point) against quadrature.
import { describe, expect, it } from 'vitest';
import { microfacetBRDF } from '../../src/math/brdf.js';
import {
  dfgSplitSum,
  directionFromCos,
  hemisphereIntegral,
  sampleCone,
  sampleCosine,
} from '../../src/math/integrate.js';
import { sphereLightCLight, sphereLightNormalization, sphereLightRepresentativeDir } from '../../src/math/lighting.js';
import { diffuseLambert } from '../../src/math/diffuse.js';

const params = (f0, alpha) => ({ F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', f0, alpha });
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('split-sum DFG term', () => {
  // independent: the midpoint rule over the hemisphere of the whole BRDF, once with F0 = 0 and once with F0 = 1
  it.each([
    [0.9, 0.3],
    [0.5, 0.5],
    [0.2, 0.8],
    [1, 1],
  ])('at mu = %f, alpha = %f matches ∫ f (n·l) with F0 = 0 and 1', (mu, alpha) => {
    const v = directionFromCos(mu);
    const [scale, bias] = dfgSplitSum(mu, alpha);
    const withF0 = (f0) => hemisphereIntegral((l) => microfacetBRDF(l, v, params(f0, alpha)), 200);
    expect(bias).toBeCloseTo(withF0(0), 2);
    expect(scale + bias).toBeCloseTo(withF0(1), 2);
  });
  it('gives F0·scale + bias = F0 for a mirror seen head on', () => {
    const [s, b] = dfgSplitSum(1, 1e-4);
    expect(s).toBeCloseTo(1, 6);
    expect(b).toBeCloseTo(0, 9);
  });
});

describe('samplers', () => {
  const mean = (sample, g, n = 20000) => {
    let sum = 0;
    for (let i = 0; i < n; i++) sum += g(sample((i + 0.5) / n, (i * 0.618033988749895) % 1));
    return sum / n;
  };
  it('cosine sampling has pdf (n·l)/π: the mean of π·1/(n·l)·(n·l)² is ∫ (n·l)² dω = 2π/3', () => {
    expect(mean(sampleCosine, (l) => Math.PI * l[2])).toBeCloseTo((2 * Math.PI) / 3, 3);
  });
  it(
    'cone sampling is uniform in solid angle: ' + 'directions stay in the cone and the mean cosine is (1 + cosMax)/2',
    () => {
      const cosMax = Math.cos(0.3);
      expect(
        mean(
          (u1, u2) => sampleCone(u1, u2, cosMax),
          (l) => l[2],
        ),
      ).toBeCloseTo((1 + cosMax) / 2, 6);
      expect(sampleCone(1, 0.3, cosMax)[2]).toBeCloseTo(cosMax, 12);
      expect(Math.hypot(...sampleCone(0.4, 0.3, cosMax))).toBeCloseTo(1, 12);
    },
  );
});

describe('sphere light', () => {
  it('c_light is the radiance of a white Lambertian surface facing the light (quadrature over the cap)', () => {
    const theta = 0.2;
    const L = 7;
    const cap = [0, 0, 1];
    const radiance = hemisphereIntegral((l) => (dot(l, cap) >= Math.cos(theta) ? diffuseLambert(1) * L : 0), 1200);
    expect(sphereLightCLight(L, Math.sin(theta))).toBeCloseTo(radiance, 2);
  });
  it('the representative point is the reflected direction when the ray meets the light, else the nearest edge', () => {
    const d = [0, 0, 1];
    const inside = [0.02, 0, Math.sqrt(1 - 0.0004)];
    expect(sphereLightRepresentativeDir(inside, d, 0.1)).toEqual(inside.map((x) => expect.closeTo(x, 12)));
    const outside = [Math.sin(0.5), 0, Math.cos(0.5)];
    const p = sphereLightRepresentativeDir(outside, d, Math.sin(0.1));
    expect(Math.hypot(...p)).toBeCloseTo(1, 12);
    expect(p[1]).toBe(0);
    expect(p[0]).toBeGreaterThan(0); // toward the ray
    expect(Math.acos(dot(p, d))).toBeLessThanOrEqual(0.1 + 1e-9); // on the light
  });
  it('the normalisation is 1 for a point light and falls as the light grows', () => {
    expect(sphereLightNormalization(0.3, 0)).toBe(1);
    expect(sphereLightNormalization(0.3, 0.2)).toBeCloseTo((0.3 / 0.4) ** 2, 12);
    expect(sphereLightNormalization(0, 0.2)).toBe(0);
    expect(sphereLightNormalization(0, 0)).toBe(1);
  });
});
