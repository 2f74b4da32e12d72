import { describe, expect, it } from 'vitest';
import { ALBEDO_TABLE_SIZE, albedoLossTableGGX, buildAlbedoTableGGX, specularAlbedoFromTable } from '../../src/math/albedo-table.js';
import { compensatedAlbedoGGX } from '../../src/math/multiple-scattering.js';
import { averageAlbedo } from '../../src/math/integrate.js';
import { albedoGGXQuadrature } from './integration-helpers.js';

const exact = (mu, alpha) => albedoGGXQuadrature(mu, alpha, 8); // within 2e-7 of the converged value
const table = buildAlbedoTableGGX(ALBEDO_TABLE_SIZE, (mu, alpha) => [exact(mu, alpha), 0]);

/** Largest |table - exact| of 1 - E over a 40 x 40 grid of (mu, alpha) in [lo, 1]², off the nodes. */
function worstError(lo) {
  let worst = 0;
  for (let i = 0; i < 40; i++) {
    for (let j = 0; j < 40; j++) {
      const [mu, alpha] = [lo + ((1 - lo) * (i + 0.37)) / 40, lo + ((1 - lo) * (j + 0.61)) / 40];
      worst = Math.max(worst, Math.abs(albedoLossTableGGX(table, mu, alpha)[0] - (1 - exact(mu, alpha))));
    }
  }
  return worst;
}

describe('the albedo table the GPU reads (bilinear in sqrt(mu), sqrt(alpha))', { timeout: 60_000 }, () => {
  it('returns 1 - E and 1 - E_avg of the function it was built from at its nodes (float32 rounding)', () => {
    for (const [i, j] of [[0, 0], [5, 9], [30, 63], [63, 20]]) {
      const [mu, alpha] = [(i / 63) ** 2, (j / 63) ** 2];
      const [loss, lossAvg] = albedoLossTableGGX(table, mu, alpha);
      expect(loss).toBeCloseTo(1 - exact(mu, alpha), 7);
      expect(lossAvg).toBeCloseTo(1 - averageAlbedo((m) => exact(m, alpha)), 7);
    }
  });

  it('interpolates E to 5e-4 for mu, alpha >= 0.01 and 3e-4 for mu, alpha >= 0.05 (independent quadrature)', () => {
    expect(worstError(0.01)).toBeLessThan(5e-4);
    expect(worstError(0.05)).toBeLessThan(3e-4);
  });

  it('gives, at its nodes, the float64 albedo with each compensation (compensatedAlbedoGGX, adaptive split sum) to 4e-4', () => {
    const shipped = buildAlbedoTableGGX(9); // nodes at mu, alpha = (i/8)²
    for (const [i, j] of [[1, 1], [3, 6], [8, 4], [5, 8]]) {
      const [mu, alpha] = [(i / 8) ** 2, (j / 8) ** 2];
      for (const f0 of [0.04, 0.71, 1]) {
        for (const c of ['none', 'kullaConty', 'turquin']) {
          // the table's 12-node split sum is within 3.5e-4 of the adaptive one (largest at grazing, small alpha)
          expect(Math.abs(specularAlbedoFromTable(shipped, mu, alpha, f0, c) - compensatedAlbedoGGX(mu, alpha, f0, c))).toBeLessThan(4e-4);
        }
      }
    }
  });
});
