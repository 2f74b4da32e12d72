import { describe, expect, it } from 'vitest';
import { ndfGGX } from '../../src/math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';

// ∫ D(m)(n·m) dω over the hemisphere = ∫_0^1 D(c) c 2π dc (D depends on c = n·m only), by Gauss-Legendre
// on a substitution that concentrates samples near c = 1 where narrow lobes live.
function projectedIntegral(D) {
  const N = 4000;
  let sum = 0;
  for (let i = 0; i < N; i++) {
    const t = (i + 0.5) / N; // midpoint rule in t, c = 1 - t^4
    const c = 1 - t ** 4;
    sum += D(c) * c * 2 * Math.PI * 4 * t ** 3;
  }
  return sum / N;
}

describe('ndfGGX', () => {
  it('is normalised: ∫ D (n·m) dω = 1 across roughness', () => {
    for (const a of [0.01, 0.05, 0.1, 0.3, 0.6, 1]) expect(projectedIntegral((c) => ndfGGX(c, a))).toBeCloseTo(1, 3);
  });
  it('equals the textbook form where that form is well conditioned', () => {
    const textbook = (c, a) => (a * a) / (Math.PI * (c * c * (a * a - 1) + 1) ** 2);
    for (const a of [0.1, 0.5, 1]) for (const c of [0.1, 0.5, 0.9, 1]) expect(ndfGGX(c, a)).toBeCloseTo(textbook(c, a), 10);
  });
  it('peaks at 1/(pi alpha²) and stays finite down to alpha = 1e-4 (and alpha = 0 is clamped)', () => {
    expect(ndfGGX(1, 1e-4)).toBeCloseTo(1 / (Math.PI * 1e-8), -2);
    expect(Number.isFinite(ndfGGX(1, 0))).toBe(true);
    expect(ndfGGX(0, 0.5)).toBe(0);
    expect(ndfGGX(-0.3, 0.5)).toBe(0);
  });
  it('keeps its float32 value at c = 1 where the textbook denominator cancels', () => {
    const f = Math.fround;
    for (const a of [1e-4, 3e-4]) {
      const c = 1;
      // textbook in float32: a² - 1 rounds to -1 (or nearly), so c²(a² - 1) + 1 is 0 (D = Inf) or far off
      const den32 = f(f(f(c * c) * f(f(a * a) - 1)) + 1);
      const textbook32 = f(a * a) / f(Math.PI * f(den32 * den32));
      expect(Math.abs(textbook32 - ndfGGX(c, a)) / ndfGGX(c, a)).toBeGreaterThan(0.2);
      // the stable form, evaluated step by step in float32, keeps 1/(pi a²)
      const d32 = f(f(f(a * a) * f(c * c)) + f(f(1 - c) * f(1 + c)));
      const t32 = f(a / d32);
      expect(Math.abs(f(t32 * t32) / Math.PI - ndfGGX(c, a)) / ndfGGX(c, a)).toBeLessThan(1e-6);
    }
  });
});

describe('visibilitySmithGGXCorrelated', () => {
  it('matches Heitz 2014 G2 = 1 / (1 + Λ(l) + Λ(v)) divided by (n·l)(n·v)', () => {
    const lambda = (c, a) => (-1 + Math.sqrt(1 + (a * a * (1 - c * c)) / (c * c))) / 2;
    for (const a of [0.05, 0.3, 1]) {
      for (const nl of [0.05, 0.4, 1]) {
        for (const nv of [0.1, 0.7, 1]) {
          const G = 1 / (1 + lambda(nl, a) + lambda(nv, a));
          expect(visibilitySmithGGXCorrelated(nl, nv, a)).toBeCloseTo(G / (nl * nv), 10);
        }
      }
    }
  });
  it('is 0 at and below the horizon and never NaN or Inf in its domain', () => {
    expect(visibilitySmithGGXCorrelated(0, 0.5, 0.3)).toBe(0);
    expect(visibilitySmithGGXCorrelated(0.5, -0.1, 0.3)).toBe(0);
    for (const a of [0, 1e-5, 1e-4, 1]) for (const c of [1e-7, 1e-4, 1]) expect(Number.isFinite(visibilitySmithGGXCorrelated(c, c, a))).toBe(true);
  });
});
