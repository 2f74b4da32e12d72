import { describe, expect, it } from 'vitest';
import { albedoGGX, averageAlbedo } from '../../src/math/integrate.js';
import { gaussLegendre } from '../../src/math/quadrature.js';
import { fresnelSchlick } from '../../src/math/fresnel.js';
import {
  averageAlbedoGGX,
  energyCompensationTurquin,
  fresnelAverage,
  fresnelMultipleScatteringKullaConty,
  multipleScatteringFromLoss,
  multipleScatteringKullaConty,
} from '../../src/math/multiple-scattering.js';
import { albedoGGXQuadrature, integrateGL } from '../support/integration-helpers.js';

const ALPHAS = [0.05, 0.2, 0.5, 0.8, 1];
const MUS = [0.05, 0.2, 0.5, 0.8, 1];

/** E_avg by the independent quadrature: 24-node Gauss–Legendre in s = sqrt(mu) of the nested-quadrature E. */
const referenceAverage = (alpha) =>
  integrateGL((s) => 4 * albedoGGXQuadrature(s * s, alpha) * s ** 3, 0, 1, gaussLegendre(24));

describe("the independent albedo quadrature (the tests' truth)", { timeout: 60_000 }, () => {
  it('gives 1 - ln 2 at alpha = 1, normal incidence (closed form)', () => {
    expect(albedoGGXQuadrature(1, 1)).toBeCloseTo(1 - Math.log(2), 12);
  });

  it('is converged: 24 and 32 nodes per panel agree to 1e-8 over mu and alpha, grazing included', () => {
    for (const alpha of [1e-3, 0.01, ...ALPHAS]) {
      for (const mu of [1e-3, ...MUS])
        expect(Math.abs(albedoGGXQuadrature(mu, alpha, 24) - albedoGGXQuadrature(mu, alpha, 32))).toBeLessThan(1e-8);
    }
  });
});

describe('the cosine-weighted average (averageAlbedo)', () => {
  it('2 ∫ mu^k mu dmu = 2/(k + 2) for k = 0, 0.5, 1, 3 (closed form)', () => {
    for (const k of [0, 0.5, 1, 3]) expect(averageAlbedo((mu) => mu ** k)).toBeCloseTo(2 / (k + 2), 12);
  });
});

describe('E_avg (Kulla & Conty 2017)', { timeout: 60_000 }, () => {
  it('the 16-node rule on the exact E matches the 24-node reference to 1e-7 (the rule adds no error)', () => {
    for (const alpha of [1e-3, ...ALPHAS]) {
      expect(Math.abs(averageAlbedo((mu) => albedoGGXQuadrature(mu, alpha)) - referenceAverage(alpha))).toBeLessThan(
        1e-7,
      );
    }
  });

  it('averageAlbedoGGX agrees with the independent quadrature to 1e-5', () => {
    for (const alpha of [1e-3, 0.01, ...ALPHAS])
      expect(Math.abs(averageAlbedoGGX(alpha) - referenceAverage(alpha))).toBeLessThan(1e-5);
  });
});

describe('Kulla–Conty multiple-scattering lobe', { timeout: 60_000 }, () => {
  /** ∫ f_ms(l, v)(n·l) dω_l by the midpoint rule, 200 cells in s = sqrt(n·l): (n·l) dω = 2π s² · 2s ds. */
  const lobeIntegral = (f, n = 200) => {
    let sum = 0;
    for (let i = 0; i < n; i++) {
      const s = (i + 0.5) / n;
      sum += f(s * s) * s * s * 2 * s;
    }
    return (2 * Math.PI * sum) / n;
  };

  it('closes the white furnace with the exact E: E(mu) + ∫ f_ms (n·l) dω = 1 to 1e-4 (independent quadrature)', () => {
    for (const alpha of ALPHAS) {
      const exact = (mu) => albedoGGXQuadrature(mu, alpha, 12);
      const Eavg = averageAlbedo(exact);
      const El = new Map();
      const E = (mu) => El.get(mu) ?? El.set(mu, exact(mu)).get(mu);
      for (const mu of MUS) {
        const integral = lobeIntegral((nl) => multipleScatteringFromLoss(1 - E(nl), 1 - E(mu), 1 - Eavg));
        expect(Math.abs(E(mu) + integral - 1)).toBeLessThan(1e-4);
      }
    }
  });

  it('closes the white furnace as shipped: albedoGGX(mu) + ∫ multipleScatteringKullaConty (n·l) dω = 1 to 1e-3', () => {
    for (const alpha of [0.2, 0.6, 1]) {
      for (const mu of [0.1, 0.5, 1]) {
        const integral = lobeIntegral((nl) => multipleScatteringKullaConty(nl, mu, alpha), 100);
        expect(Math.abs(albedoGGX(mu, alpha) + integral - 1)).toBeLessThan(1e-3);
      }
    }
  });

  it('is the closed form (1 - E_l)(1 - E_v) / (pi (1 - E_avg)), symmetric in l and v, and 0 below the horizon', () => {
    const [El, Ev, Eavg] = [albedoGGX(0.3, 0.7), albedoGGX(0.9, 0.7), averageAlbedoGGX(0.7)];
    expect(multipleScatteringKullaConty(0.3, 0.9, 0.7)).toBeCloseTo(((1 - El) * (1 - Ev)) / (Math.PI * (1 - Eavg)), 12);
    expect(multipleScatteringKullaConty(0.9, 0.3, 0.7)).toBeCloseTo(multipleScatteringKullaConty(0.3, 0.9, 0.7), 12);
    expect(multipleScatteringKullaConty(-0.1, 0.5, 0.7)).toBe(0);
    expect(multipleScatteringFromLoss(0, 0, 0)).toBe(0); // a mirror loses nothing: no lobe, no 0/0
  });
});

describe('Fresnel of the bounces', () => {
  it('fresnelAverage is 2 ∫ F_Schlick(mu) mu dmu (Gauss–Legendre, exact for this degree-6 polynomial)', () => {
    const rule = gaussLegendre(8);
    for (const f0 of [0, 0.04, 0.5, 0.95, 1]) {
      expect(fresnelAverage(f0)).toBeCloseTo(
        integrateGL((mu) => 2 * fresnelSchlick(f0, mu) * mu, 0, 1, rule),
        14,
      );
    }
  });

  it('the Kulla–Conty factor is the series Σ F_avg^(k+2) E_avg (1 - E_avg)^k, and 1 when F_avg = 1', () => {
    for (const [fAvg, eAvg] of [
      [0.1, 0.4],
      [0.5, 0.41],
      [0.95, 0.6],
      [1, 0.409],
      [0.7, 0.99],
    ]) {
      let series = 0;
      for (let k = 0; k < 5000; k++) series += fAvg ** (k + 2) * eAvg * (1 - eAvg) ** k;
      expect(fresnelMultipleScatteringKullaConty(fAvg, eAvg)).toBeCloseTo(series, 12);
    }
    expect(fresnelMultipleScatteringKullaConty(1, 0.409)).toBeCloseTo(1, 14);
  });

  it("Turquin's factor closes the furnace at f0 = 1 (E · factor = 1) and is 1 at f0 = 0", () => {
    for (const E of [0.3, 0.5, 0.9, 1]) {
      expect(E * energyCompensationTurquin(1, E)).toBeCloseTo(1, 14);
      expect(energyCompensationTurquin(0, E)).toBe(1);
      expect(energyCompensationTurquin(0.5, E)).toBeCloseTo((E + 0.5 * (1 - E)) / E, 14); // 1 + f0 (1 - E)/E
    }
  });
});
