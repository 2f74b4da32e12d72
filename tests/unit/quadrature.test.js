// The quadrature rules of src/math/quadrature.js against closed-form integrals.
import { describe, expect, it } from 'vitest';
import { gaussLegendre, gaussLegendreVector, integrate, integrateVector } from '../../src/math/quadrature.js';

describe('Gauss-Legendre', () => {
  it.each([1, 2, 5, 16, 48])('the %i-point rule integrates x^k exactly on [-1, 1] for k < 2n', (n) => {
    const { x, w } = gaussLegendre(n);
    for (let k = 0; k < 2 * n; k++) {
      const exact = k % 2 ? 0 : 2 / (k + 1);
      expect(x.reduce((s, xi, i) => s + w[i] * xi ** k, 0)).toBeCloseTo(exact, 12);
    }
  });
  it('maps to [a, b]: ∫_0^π sin = 2 with 12 nodes', () => {
    expect(gaussLegendreVector((t) => [Math.sin(t)], 0, Math.PI, 12, 1)[0]).toBeCloseTo(2, 13);
  });
});

describe('adaptive Gauss-Kronrod', () => {
  it('meets its tolerance on a kink, an endpoint singularity and a narrow peak (closed forms)', () => {
    expect(integrate((x) => Math.abs(x - 0.3), 0, 1, 1e-12)).toBeCloseTo(0.29, 11);
    expect(integrate((x) => 1 / Math.sqrt(x), 0, 1, 1e-10)).toBeCloseTo(2, 8);
    const a = 1e-3; // ∫ a/(π(x² + a²)) over [-1, 1] = (2/π) atan(1/a)
    const lorentz = (x) => a / (Math.PI * (x * x + a * a));
    expect(integrate(lorentz, -1, 1, 1e-11)).toBeCloseTo((2 / Math.PI) * Math.atan(1 / a), 10);
  });
  it('integrates each component of a vector-valued function, and an empty interval to 0', () => {
    const [c, s] = integrateVector((t) => [Math.cos(t), Math.sin(t)], 0, Math.PI / 2, 1e-12, 2);
    expect(c).toBeCloseTo(1, 12);
    expect(s).toBeCloseTo(1, 12);
    expect([...integrateVector(() => [1], 1, 1, 1e-9, 1)]).toEqual([0]);
  });
});

describe('averageAlbedo', () => {
  it('is 2 ∫ E μ dμ: 1 for E = 1, 2/3 for E = μ, 2/(k + 2) for E = μ^k (closed forms)', async () => {
    const { averageAlbedo } = await import('../../src/math/integrate.js');
    expect(averageAlbedo(() => 1)).toBeCloseTo(1, 13);
    for (const k of [1, 2.5, 7]) expect(averageAlbedo((mu) => mu ** k)).toBeCloseTo(2 / (k + 2), 12);
  });
});
