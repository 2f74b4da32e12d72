import { describe, expect, it } from 'vitest';
import { fresnelZone, sphereZoneFractions } from '../../src/math/zones.js';

describe('Fresnel zones', () => {
  it('classifies by angle: < 45°, 45–75°, > 75°', () => {
    const z = (deg) => fresnelZone(Math.cos((deg * Math.PI) / 180));
    expect([0, 30, 44.9, 45.1, 60, 74.9, 75.1, 89, 90].map(z)).toEqual([0, 0, 0, 1, 1, 1, 2, 2, 2]);
  });
  it('gives the orthographic sphere shares that a fine pixel grid over the disk finds', () => {
    // independent check: classify the centres of a 1200 x 1200 grid over the disk by n·v = sqrt(1 - r²)
    const N = 1200;
    const counts = [0, 0, 0];
    let n = 0;
    for (let i = 0; i < N; i++) {
      for (let j = 0; j < N; j++) {
        const x = ((i + 0.5) / N) * 2 - 1;
        const y = ((j + 0.5) / N) * 2 - 1;
        const r2 = x * x + y * y;
        if (r2 > 1) continue;
        counts[fresnelZone(Math.sqrt(1 - r2))]++;
        n++;
      }
    }
    sphereZoneFractions().forEach((f, i) => expect(Math.abs(counts[i] / n - f)).toBeLessThan(1e-3));
    expect(sphereZoneFractions()[0]).toBeCloseTo(0.5, 12);
  });
});
