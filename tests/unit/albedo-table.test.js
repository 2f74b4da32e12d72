import { describe, expect, it } from 'vitest';
import {
  ALBEDO_TABLE_SIZE,
  albedoLossTableGGX,
  buildAlbedoTableGGX,
  specularAlbedoFromTable,
} from '../../src/math/albedo-table.js';
import { compensatedAlbedoGGX } from '../../src/math/multiple-scattering.js';
import { averageAlbedo } from '../../src/math/integrate.js';
import { albedoGGXQuadrature } from '../support/integration-helpers.js';

const exact = (mu, alpha) => albedoGGXQuadrature(mu, alpha, 8); // within 2e-7 of the converged value
const table = buildAlbedoTableGGX(ALBEDO_TABLE_SIZE, (mu, alpha) => [exact(mu, alpha), 0]);

/**
 * Largest |table - exact| of 1 - E over 60 x 60 log-spaced (mu, alpha) in [lo, 1]², off the nodes: log spacing
 * puts as many points at the grazing, near-mirror corner as anywhere (a uniform grid's first point was 0.019).
 */
function worstError(lo, n = 60) {
  const at = (k) => lo * (1 / lo) ** ((k + 0.5) / n);
  let worst = 0;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      const [mu, alpha] = [at(i), at(j)];
      worst = Math.max(worst, Math.abs(albedoLossTableGGX(table, mu, alpha)[0] - (1 - exact(mu, alpha))));
    }
  }
  return worst;
}

describe('the albedo table the GPU reads (bilinear in cbrt(mu), cbrt(alpha))', { timeout: 120_000 }, () => {
  it('returns 1 - E and 1 - E_avg of the function it was built from at its nodes (float32 rounding)', () => {
    for (const [i, j] of [
      [0, 0],
      [5, 9],
      [30, 63],
      [63, 20],
    ]) {
      const [mu, alpha] = [(i / 63) ** 3, (j / 63) ** 3];
      const [loss, lossAvg] = albedoLossTableGGX(table, mu, alpha);
      expect(loss).toBeCloseTo(1 - exact(mu, alpha), 7);
      expect(lossAvg).toBeCloseTo(1 - averageAlbedo((m) => exact(m, alpha)), 7);
    }
  });

  it(
    'interpolates E to 1.3e-3 for mu, alpha >= 0.01, 8.5e-4 for >= 0.02, ' +
      '5e-4 for >= 0.05 (independent quadrature)',
    () => {
      const worst = [0.01, 0.02, 0.05].map((lo) => worstError(lo));
      console.log(
        `albedo table, worst |error| of 1 - E for mu, alpha >= 0.01, 0.02, 0.05: ` +
          `${worst.map((e) => e.toExponential(2)).join(', ')}`,
      );
      expect(worst[0]).toBeLessThan(1.3e-3);
      expect(worst[1]).toBeLessThan(8.5e-4);
      expect(worst[2]).toBeLessThan(5e-4);
    },
  );

  it(
    'gives, at its nodes, the float64 albedo with each compensation ' +
      '(compensatedAlbedoGGX, adaptive split sum) to 4e-4',
    () => {
      const shipped = buildAlbedoTableGGX(9); // nodes at mu, alpha = (i/8)³
      for (const [i, j] of [
        [2, 2],
        [3, 6],
        [8, 4],
        [5, 8],
      ]) {
        // [2, 2]: mu = alpha = 0.016
        const [mu, alpha] = [(i / 8) ** 3, (j / 8) ** 3];
        for (const f0 of [0.04, 0.71, 1]) {
          for (const c of ['none', 'kullaConty', 'turquin']) {
            // the table's 12-node split sum is within 3.5e-4 of the adaptive one (largest at grazing, small alpha)
            expect(
              Math.abs(specularAlbedoFromTable(shipped, mu, alpha, f0, c) - compensatedAlbedoGGX(mu, alpha, f0, c)),
            ).toBeLessThan(4e-4);
          }
        }
      }
    },
  );
});
