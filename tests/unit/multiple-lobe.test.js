import { describe, expect, it } from 'vitest';
import { hasMultipleLobe, kullaContyLobe, walkMultiplePart } from '../../src/widgets/brdf-lobe/multiple-lobe.js';
import { averageAlbedoGGX, fresnelAverage, multipleScatteringKullaConty } from '../../src/math/multiple-scattering.js';

describe('brdf-lobe: the multiple-scattering lobe', () => {
  const [l, v] = [
    [-0.5, 0, Math.sqrt(0.75)],
    [0.3, 0, Math.sqrt(0.91)],
  ];

  it("is Kulla & Conty's lobe, times F_avg² E_avg / (1 - F_avg (1 - E_avg)) (closed form) with Fresnel", () => {
    expect(kullaContyLobe(l, v, 0.8, 1)).toBeCloseTo(multipleScatteringKullaConty(l[2], v[2], 0.8), 12);
    const [fAvg, eAvg] = [fresnelAverage(0.5), averageAlbedoGGX(0.8)];
    expect(kullaContyLobe(l, v, 0.8, 0.5)).toBeCloseTo(
      (multipleScatteringKullaConty(l[2], v[2], 0.8) * fAvg * fAvg * eAvg) / (1 - fAvg * (1 - eAvg)),
      12,
    );
  });

  it('is drawn for GGX with height-correlated Smith only', () => {
    expect(hasMultipleLobe({ D: 'ggx', V: 'smithGGXCorrelated' })).toBe(true);
    expect(hasMultipleLobe({ D: 'beckmann', V: 'smithGGXCorrelated' })).toBe(false);
  });

  it(
    "the walk's multiply scattered part at alpha = 1, " +
      'F = 1 lies near the Kulla–Conty lobe (within 25 %: a model, not the walk)',
    () => {
      const w = walkMultiplePart(l, v, 1, 1, 3);
      expect(w.value).toBeGreaterThan(0);
      expect(Math.abs(w.value / kullaContyLobe(l, v, 1, 1) - 1)).toBeLessThan(0.25);
    },
  );
});
