import { describe, expect, it } from 'vitest';
import { albedoCurves, saturation, walkPoints } from '../../src/widgets/energy/compensation.js';
import { buildAlbedoTableGGX } from '../../src/math/albedo-table.js';
import { METALS } from '../../src/math/materials.js';
import { albedoSweep } from '../../src/widgets/energy/model.js';
import { HEAD } from '../../src/widgets/energy/table.js';
import { albedoGGX } from '../../src/math/integrate.js';

const GOLD = METALS.find((m) => m.key === 'gold').linear;
const table = buildAlbedoTableGGX(16);

describe('energy widget: compensation curves and walk points', () => {
  it(
    'both compensations return an F0 = 1 channel to albedo 1 at every angle ' + '(the furnace closes by construction)',
    () => {
      const curves = albedoCurves(table, 0.8, [1, 0.5], [0, 30, 60, 85]);
      for (const key of ['kullaConty', 'turquin']) for (const [one] of curves[key]) expect(one).toBeCloseTo(1, 6);
      for (const [one] of curves.none) expect(one).toBeLessThan(0.9);
    },
  );

  it(
    'the random walk makes rough gold more saturated than single scattering ' + '(1 - min/max of the linear colour)',
    () => {
      const [head] = walkPoints(1, GOLD);
      const [single] = albedoCurves(table, 1, GOLD, [0]).none;
      expect(saturation(head.albedo)).toBeGreaterThan(saturation(single) + 0.05);
      expect(saturation([0.5, 0.5, 0.5])).toBe(0);
    },
    30_000,
  );

  it('the table’s average is E_avg = 2∫E(μ) μ dμ, cosine-weighted (Simpson in μ), not the plain mean', () => {
    const n = 64;
    const E = Array.from({ length: n + 1 }, (_, i) => albedoGGX(i / n, 1)); // once, for both integrals
    const simpson = (g) => g.reduce((sum, x, i) => sum + (i === 0 || i === n ? 1 : i % 2 ? 4 : 2) * x, 0) / (3 * n);
    const [d] = albedoSweep({ alphas: ['1'] });
    expect(d.avg).toBeCloseTo(2 * simpson(E.map((e, i) => e * (i / n))), 4);
    const overSolidAngle = simpson(E); // ∫E dω / 2π = ∫E dμ: each direction alike
    expect(Math.abs(d.avg - overSolidAngle)).toBeGreaterThan(0.01); // so the head's words matter
    expect(HEAD).toContain('E<sub>avg</sub> = 2∫E(μ) μ dμ (cosine-weighted average)');
    expect(HEAD).not.toMatch(/averaged over the hemisphere/);
  }, 30_000);
});
