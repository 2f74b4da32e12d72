import { describe, expect, it } from 'vitest';
import { albedoCurves, saturation, walkPoints } from '../../src/widgets/energy/compensation.js';
import { buildAlbedoTableGGX } from '../../src/math/albedo-table.js';
import { METALS } from '../../src/math/materials.js';

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
});
