import { describe, expect, it } from 'vitest';
import {
  WHOLE_MILK,
  absorptionFromK,
  lambertianEntryAngle2D,
  meanFreePath,
  opticalDepth,
  randomWalk2D,
  scatteringAlbedo,
  transmittance,
  waterAbsorptionRgb,
} from '../../src/math/media.js';
import { seededRandom } from '../../src/math/microsurface.js';

describe('Beer-Lambert', () => {
  it('is exp(-sigma d), multiplicative over distance, with optical depth sigma d', () => {
    expect(transmittance(0.5, 2)).toBeCloseTo(Math.exp(-1), 15);
    expect(transmittance(0.3, 1) * transmittance(0.3, 2)).toBeCloseTo(transmittance(0.3, 3), 15);
    expect(opticalDepth(0.3, 3)).toBeCloseTo(0.9, 15);
    expect(transmittance(-1, 2)).toBe(1);
    expect(meanFreePath(4)).toBe(0.25);
    expect(scatteringAlbedo(3, 1)).toBe(0.75);
  });
  it("makes water clear over centimetres and blue-green over tens of metres (Hale & Querry's k)", () => {
    const [r, g, b] = waterAbsorptionRgb();
    expect(r).toBeCloseTo(absorptionFromK(1.64e-8, 0.65), 10); // 0.317 / m at 650 nm
    expect(r).toBeCloseTo(0.317, 3);
    for (const s of [r, g, b]) expect(transmittance(s, 0.05)).toBeGreaterThan(0.98);
    const deep = [r, g, b].map((s) => transmittance(s, 10));
    expect(deep[0]).toBeLessThan(0.05); // the red is gone
    expect(deep[1]).toBeGreaterThan(0.5);
    expect(deep[2]).toBeGreaterThan(0.5);
  });
});

describe('random walk in a 2-D slab', () => {
  it(
    'spends, on average, pi d / 2 inside a slab of thickness d whatever the ' + 'scattering (Blanco & Fournier 2003)',
    () => {
      // the mean path length of light entering a non-absorbing body evenly and from all directions is
      // pi A / P in 2-D (4V/S in 3-D), independent of the scattering coefficient; a slab gives pi d / 2
      const d = 1;
      for (const sigmaS of [0.5, 2, 8]) {
        const rand = seededRandom(42);
        let sum = 0;
        const n = 40000;
        for (let i = 0; i < n; i++)
          sum += randomWalk2D({ sigmaS, thickness: d, entryAngle: lambertianEntryAngle2D(rand), rand }).path;
        expect(Math.abs(sum / n / ((Math.PI * d) / 2) - 1)).toBeLessThan(0.015);
      }
    },
  );
  it('without scattering, transmits the cosine-weighted exp(-sigma d / cos) (closed-form quadrature)', () => {
    // sigmaS tiny: the walk is a straight line; compare its absorbed weight with the integral
    const sigmaA = 0.7;
    const d = 1;
    const rand = seededRandom(3);
    let sim = 0;
    const n = 100000;
    for (let i = 0; i < n; i++) {
      const w = randomWalk2D({ sigmaS: 1e-9, thickness: d, entryAngle: lambertianEntryAngle2D(rand), rand });
      sim += Math.exp(-sigmaA * w.path);
    }
    let exact = 0;
    const m = 20000;
    for (let i = 0; i < m; i++) {
      const t = -Math.PI / 2 + ((i + 0.5) * Math.PI) / m;
      exact += (Math.cos(t) / 2) * Math.exp((-sigmaA * d) / Math.cos(t)) * (Math.PI / m);
    }
    expect(sim / n).toBeCloseTo(exact, 2);
  });
  it('lets light out of a non-absorbing semi-infinite medium only through the entry side, eventually', () => {
    // a 2-D walk returns to its starting line with probability 1, but its expected return time is
    // infinite: the share still inside after N events falls slowly (like 1/sqrt(N)), and none leaves elsewhere
    const stillInside = (maxEvents) => {
      const rand = seededRandom(9);
      const walks = Array.from({ length: 3000 }, () => randomWalk2D({ sigmaS: 1, rand, maxEvents }));
      expect(walks.every((w) => w.exit !== 'through')).toBe(true);
      return walks.filter((w) => w.exit === 'lost').length / walks.length;
    };
    const [a, b] = [stillInside(100), stillInside(10000)];
    expect(b).toBeLessThan(a / 4);
    expect(b).toBeLessThan(0.02);
  });
});

describe('whole milk (Jensen et al. 2001, Table 2)', () => {
  it('holds the published absorption and reduced scattering, mm⁻¹ → m⁻¹, and says the scattering is reduced', () => {
    // Table 2, whole milk: σa = 0.0011, 0.0024, 0.014 and σ′s = 2.55, 3.21, 3.77 (mm⁻¹, R, G, B)
    [0.0011, 0.0024, 0.014].forEach((a, i) => expect(WHOLE_MILK.sigmaA[i]).toBeCloseTo(a * 1000, 9));
    [2.55, 3.21, 3.77].forEach((s, i) => expect(WHOLE_MILK.sigmaSReduced[i]).toBeCloseTo(s * 1000, 9));
    expect(WHOLE_MILK.source).toMatch(/reduced scattering/);
  });
});
