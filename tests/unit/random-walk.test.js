import { describe, expect, it } from 'vitest';
import {
  randomWalkAlbedoGGX,
  randomWalkBRDFGGX,
  sampleVisibleNormalGGX,
  WALK_MAX_BOUNCES,
} from '../../src/math/random-walk.js';
import { microfacetBRDF } from '../../src/math/brdf.js';
import { ndfGGX } from '../../src/math/ndf.js';
import { seededRandom } from '../../src/math/microsurface.js';
import { METALS } from '../../src/math/materials.js';
import { albedoGGXQuadrature } from '../support/integration-helpers.js';

const GRID = [
  [1, 1],
  [0.5, 0.3],
  [0.1, 0.6],
  [0.05, 0.05],
  [0.9, 0.01],
  [0.3, 1],
  [0.7, 0.5],
];
const SIGMAS = 4; // seeded, so deterministic; 4 standard errors is a 6e-5 two-sided chance per check

describe('random walk on the Smith microsurface (Heitz et al. 2016)', { timeout: 60_000 }, () => {
  it(`loses nothing with F = 1: albedo 1 up to the paths dropped after ${WALK_MAX_BOUNCES} bounces`, () => {
    for (const [mu, alpha] of GRID) {
      const r = randomWalkAlbedoGGX(mu, alpha, 1, 20000, 11);
      // with F = 1 every path that leaves carries weight 1: the albedo is exactly 1 - dropped, its error 0
      expect(r.albedo).toBeCloseTo(1 - r.dropped, 14);
      expect(r.dropped).toBeLessThan(1e-4);
    }
  });

  it(
    'its first bounce is the single-scattering albedo E(mu) (independent ' + 'quadrature), within 4 standard errors',
    () => {
      for (const [mu, alpha] of GRID) {
        const r = randomWalkAlbedoGGX(mu, alpha, 1, 40000, 5);
        const E = albedoGGXQuadrature(mu, alpha);
        expect(Math.abs(r.single - E)).toBeLessThanOrEqual(SIGMAS * r.singleStandardError + 1e-9);
      }
    },
  );

  it('its BRDF by next-event estimation: first bounce = D V / 4 (F = 1) within 4 standard errors', () => {
    const l = [0.6, 0, 0.8];
    for (const v of [
      [-0.3, 0.4, Math.sqrt(0.75)],
      [0.6, 0, 0.8],
      [-0.99, 0, Math.sqrt(1 - 0.99 ** 2)],
    ]) {
      for (const alpha of [0.3, 0.7, 1]) {
        const r = randomWalkBRDFGGX(l, v, alpha, 1, 20000, 3);
        const single = microfacetBRDF(l, v, { F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated', alpha, f0: 1 });
        expect(Math.abs(r.single - single)).toBeLessThanOrEqual(SIGMAS * r.singleStandardError + 1e-12);
        expect(r.value).toBeGreaterThan(r.single);
      }
    }
  });

  it('its BRDF is reciprocal, f(l, v) = f(v, l), all bounces, within 4 combined standard errors', () => {
    const [l, v] = [
      [0.8, 0, 0.6],
      [-0.2, 0.3, Math.sqrt(1 - 0.13)],
    ];
    for (const alpha of [0.5, 1]) {
      const a = randomWalkBRDFGGX(l, v, alpha, 1, 40000, 8);
      const b = randomWalkBRDFGGX(v, l, alpha, 1, 40000, 9);
      expect(Math.abs(a.value - b.value)).toBeLessThanOrEqual(SIGMAS * Math.hypot(a.standardError, b.standardError));
    }
  });

  it("gold's colour per channel: each channel equals a scalar walk with that f0 and the same seed", () => {
    const gold = METALS.find((m) => m.key === 'gold').linear;
    const rgb = randomWalkAlbedoGGX(0.5, 0.8, gold, 5000, 4);
    gold.forEach((f0, c) => expect(rgb.albedo[c]).toBeCloseTo(randomWalkAlbedoGGX(0.5, 0.8, f0, 5000, 4).albedo, 14));
    expect(randomWalkAlbedoGGX(0.5, 0.8, 0.5, 5000, 4)).toEqual(randomWalkAlbedoGGX(0.5, 0.8, 0.5, 5000, 4)); // seeded
  });
});

describe(
  'visible-normal sampling inside the walk (Dupuy & Benyoub 2023), both hemispheres',
  { timeout: 60_000 },
  () => {
    it('mean of m over the samples matches ∫ m max(0, wi·m) D(m) dω / ∫ max(0, wi·m) D(m) dω (quadrature)', () => {
      const alpha = 0.6;
      for (const wi of [
        [0.6, 0, 0.8],
        [0.8, 0, -0.6],
        [0, 0.28, -0.96],
      ]) {
        const rand = seededRandom(2);
        const n = 200000;
        const mean = [0, 0, 0];
        for (let i = 0; i < n; i++)
          sampleVisibleNormalGGX(wi, alpha, rand(), rand()).forEach((x, k) => (mean[k] += x / n));
        // midpoint rule over the hemisphere of normals
        const want = [0, 0, 0];
        let norm = 0;
        const N = 400;
        for (let i = 0; i < N; i++) {
          const c = (i + 0.5) / N;
          const s = Math.sqrt(1 - c * c);
          for (let j = 0; j < 2 * N; j++) {
            const phi = (Math.PI * (j + 0.5)) / N;
            const m = [s * Math.cos(phi), s * Math.sin(phi), c];
            const w = Math.max(0, wi[0] * m[0] + wi[1] * m[1] + wi[2] * m[2]) * ndfGGX(c, alpha);
            norm += w;
            m.forEach((x, k) => (want[k] += w * x));
          }
        }
        want.forEach((x, k) => expect(mean[k]).toBeCloseTo(x / norm, 2));
      }
    });
  },
);
