// The directional albedos OpenPBR's layering reads, against independent integrals: the shipped dielectric table
// (src/math/openpbr-albedo.data.js) against the adaptive quadrature and against a plain quadrature over the half
// vector written in the test; EON's exact albedo and white furnace; the fuzz lobe's LTC normalisation, so that its
// albedo is Zeltner's R, as the specification's layering assumes.
import { describe, expect, it } from 'vitest';
import {
  OPENPBR_ALBEDO_DIMS,
  buildOpenPbrAlbedoTable,
  dielectricAlbedoQuadrature,
  fresnelDielectricAverage,
  openPbrAlbedoTable,
  openPbrDielectricAlbedo,
} from '../../src/math/openpbr-albedo.js';
import {
  albedoFujiiOrenNayar,
  averageAlbedoFujiiOrenNayar,
  diffuseEON,
  diffuseFujiiOrenNayar,
} from '../../src/math/openpbr-diffuse.js';
import { albedoFuzzZeltner, fuzzZeltner } from '../../src/math/openpbr-fuzz.js';
import { fresnelDielectric } from '../../src/math/fresnel.js';
import { ndfGGX } from '../../src/math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../src/math/visibility.js';
import { albedoOverDirections, albedoOverHalfVector } from '../support/openpbr-quadrature.js';

const view = (mu) => [Math.sqrt((1 - mu) * (1 + mu)), 0, mu];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('the dielectric albedo table E(μ, α, η)', () => {
  it('holds, at its nodes, the float64 quadrature it is built from (a rebuilt slice, 16 nodes per piece)', () => {
    const { mu, alpha } = OPENPBR_ALBEDO_DIMS;
    const rebuilt = buildOpenPbrAlbedoTable((m, a, eta) => (eta === 1 || eta > 1e5 || m > 0.5 ? NaN : 0));
    const shipped = openPbrAlbedoTable();
    // every node of slice k = 9 (η = 1.24) with μ ≤ 0.5, recomputed
    let checked = 0;
    for (let i = 0; i < mu; i += 5) {
      for (let j = 0; j < alpha; j += 5) {
        const [m, a, z] = [(i / (mu - 1)) ** 3, (j / (alpha - 1)) ** 3, 9 / (OPENPBR_ALBEDO_DIMS.r - 1)];
        const eta = (1 + z * z) / (1 - z * z);
        const e = openPbrDielectricAlbedo(m, a, eta, shipped);
        expect(e).toBeCloseTo(dielectricAlbedoQuadrature(m, a, eta, 16), 6);
        checked++;
      }
    }
    expect(checked).toBe(49);
    expect(rebuilt.data.length).toBe(shipped.data.length);
  });

  it('is within its stated error of the adaptive quadrature: 1.5e-3 at α ≥ 0.05, 1.2e-2 below', () => {
    const mus = [1e-3, 0.005, 0.02, 0.07, 0.15, 0.33, 0.6, 0.85, 1];
    const alphas = [0.001, 0.012, 0.03, 0.06, 0.13, 0.27, 0.45, 0.8];
    const etas = [1.01, 1.07, 1.33, 1.45, 1.6, 2.1, 2.9, 4];
    let [rough, smooth] = [0, 0];
    for (const mu of mus) {
      for (const a of alphas) {
        for (const eta of etas) {
          const err = Math.abs(openPbrDielectricAlbedo(mu, a, eta) - dielectricAlbedoQuadrature(mu, a, eta, 16));
          if (a >= 0.05) rough = Math.max(rough, err);
          else smooth = Math.max(smooth, err);
        }
      }
    }
    console.log(`albedo table: worst error ${rough.toExponential(2)} at α ≥ 0.05, ${smooth.toExponential(2)} below`);
    // the worst: η = 1.01 next to the node at η = 1 (1.2e-3 at α = 0.06), and near-mirrors at grazing view (1.1e-2
    // at α = 0.001, μ = 0.005), where the dip is narrower than a cell
    expect(rough).toBeLessThan(1.5e-3);
    expect(smooth).toBeLessThan(1.2e-2);
  });

  it("the quadrature equals a plain half-vector integral of the catalogue's GGX × Smith × exact Fresnel", () => {
    for (const [mu, a, eta] of [
      [1, 1e-4, 1.5],
      [0.5, 0.09, 1.6],
      [0.05, 0.3, 1.33],
      [0.01, 1, 2.4],
    ]) {
      const v = view(mu);
      const lobe = (l) => {
        const h = l.map((x, i) => x + v[i]);
        const n = Math.hypot(...h);
        return [
          (fresnelDielectric(dot(l, h) / n, eta) * ndfGGX(h[2] / n, a) * visibilitySmithGGXCorrelated(l[2], mu, a)) / 4,
        ];
      };
      expect(albedoOverHalfVector(lobe, v, a, 64, 1)[0]).toBeCloseTo(dielectricAlbedoQuadrature(mu, a, eta), 7);
    }
  });
});

describe('EON, the base diffuse lobe (Portsmouth et al. 2024)', () => {
  const rs = [0, 0.3, 0.7, 1];
  const mus = [1, 0.6, 0.2, 0.05];
  it("Fujii's Oren–Nayar: the closed-form albedo and its average equal quadratures of the lobe", () => {
    for (const r of rs) {
      for (const mu of mus) {
        const v = view(mu);
        const E = albedoOverDirections((l) => [diffuseFujiiOrenNayar(l[2], mu, dot(l, v), r)], 96, 1)[0];
        expect(albedoFujiiOrenNayar(mu, r)).toBeCloseTo(E, 4); // the lobe's kink at n·l = n·v: the quadrature's 1e-5
      }
      const nodes = Array.from({ length: 400 }, (_, i) => (i + 0.5) / 400);
      const avg = nodes.reduce((s, mu) => s + 2 * albedoFujiiOrenNayar(mu, r) * mu, 0) / 400;
      expect(averageAlbedoFujiiOrenNayar(r)).toBeCloseTo(avg, 5);
    }
  });
  it('passes the white furnace (ρ = 1: albedo 1 at every angle) and reduces to Lambert at r = 0', () => {
    for (const r of rs) {
      for (const mu of mus) {
        const v = view(mu);
        const E = albedoOverDirections((l) => [diffuseEON(l[2], mu, dot(l, v), r, 1)], 96, 1)[0];
        expect(E).toBeCloseTo(1, 4);
      }
    }
    expect(diffuseEON(0.3, 0.8, 0.1, 0, 0.5)).toBeCloseTo(0.5 / Math.PI, 15);
  });
  it('is reciprocal', () => {
    expect(diffuseEON(0.3, 0.8, 0.5, 0.6, 0.7)).toBeCloseTo(diffuseEON(0.8, 0.3, 0.5, 0.6, 0.7), 15);
  });
});

describe("the fuzz lobe (Zeltner, Burley & Chiang 2022, MaterialX's fits)", () => {
  it("its LTC lobe integrates to 1, so the lobe's albedo is R(n·v, r), as the layering takes it", () => {
    for (const r of [0.01, 0.25, 0.5, 1]) {
      for (const mu of [1, 0.7, 0.3, 0.05]) {
        const v = view(mu);
        const E = albedoOverDirections((l) => [fuzzZeltner(l, v, r)], 96, 1)[0];
        expect(E).toBeCloseTo(albedoFuzzZeltner(mu, r), 6);
        expect(albedoFuzzZeltner(mu, r)).toBeGreaterThanOrEqual(0);
        expect(albedoFuzzZeltner(mu, r)).toBeLessThan(1);
      }
    }
  });
});

describe('fresnelDielectricAverage', () => {
  // the closed form of 2∫F μ dμ for the exact dielectric Fresnel (the integral done term by term), in float64
  const closedForm = (n) => {
    const [n2, n4] = [n * n, n ** 4];
    return (
      0.5 +
      ((n - 1) * (3 * n + 1)) / (6 * (n + 1) ** 2) +
      ((n2 * (n2 - 1) ** 2) / (n2 + 1) ** 3) * Math.log((n - 1) / (n + 1)) -
      (2 * n ** 3 * (n2 + 2 * n - 1)) / ((n2 + 1) * (n4 - 1)) +
      ((8 * n4 * (n4 + 1)) / ((n2 + 1) * (n4 - 1) ** 2)) * Math.log(n)
    );
  };
  it('its 16-point rule is within 5e-9 of the closed form for η in (1, 100] (3e-10 for η ≤ 10)', () => {
    for (const eta of [1.01, 1.05, 1.2, 1.33, 1.5, 1.6, 2, 2.4, 3, 5, 10, 100]) {
      expect(Math.abs(fresnelDielectricAverage(eta) - closedForm(eta))).toBeLessThan(eta <= 10 ? 3e-10 : 5e-9);
    }
    expect(fresnelDielectricAverage(1)).toBe(0);
  });
});
