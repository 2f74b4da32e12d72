// F82-tint (Hoffman 2023; OpenPBR Surface's metal Fresnel) against independent truths: the exact conductor
// Fresnel equations of the talk's five metals (measured n, k), Schlick's approximation, and the formula as the
// specification and MaterialX's mx_fresnel_hoffman_schlick write it (pow, mix), transcribed here in float64.
import { describe, expect, it } from 'vitest';
import {
  F82_MU,
  conductorIorFromF0EdgeTint,
  edgeTintFromConductorIor,
  f82TintFromConductor,
  fresnelConductor,
  fresnelF82Tint,
  fresnelSchlick,
} from '../../src/math/fresnel.js';
import { METALS } from '../../src/math/materials.js';
import { measuredRgbNk } from '../../src/math/optical-constants.js';
import { FRESNEL_FAMILY } from '../../src/math/catalogue/fresnel-terms.js';
import { angleGrid, errorTable } from '../../src/widgets/metal-fresnel/model.js';

const channels = METALS.flatMap((m) => measuredRgbNk(m.key).map(([eta, k], i) => ({ name: `${m.key} ${i}`, eta, k })));
const mus = Array.from({ length: 201 }, (_, i) => i / 200);
const grid = [0, 0.02, 0.04, 0.3, 0.5, 0.9, 0.95, 1];

/** OpenPBR's form with MaterialX's spelling: mix(F0, 1, (1 − μ)^5) − a μ (1 − μ)^6, a from F82 at 1/7. */
const openPbrF82 = (f0, f82, mu) => {
  const mix = (a, b, t) => a * (1 - t) + b * t;
  const a = (mix(f0, 1, Math.pow(1 - 1 / 7, 5)) * (1 - f82)) / ((1 / 7) * Math.pow(1 - 1 / 7, 6));
  return mix(f0, 1, Math.pow(1 - mu, 5)) - a * mu * Math.pow(1 - mu, 6);
};

describe('fresnelF82Tint', () => {
  it('equals the specification’s formula as MaterialX writes it (mix, pow), wherever that is in [0, 1]', () => {
    let worst = 0;
    for (const f0 of grid)
      for (const tint of grid)
        for (const mu of mus) {
          const ref = openPbrF82(f0, tint, mu);
          if (ref >= 0 && ref <= 1) worst = Math.max(worst, Math.abs(fresnelF82Tint(f0, tint, mu) - ref));
        }
    expect(worst).toBeLessThan(1e-13);
  });

  it('equals Schlick’s approximation when the tint is 1', () => {
    for (const f0 of grid) for (const mu of mus) expect(fresnelF82Tint(f0, 1, mu)).toBe(fresnelSchlick(f0, mu));
  });

  it('meets tint × Schlick(f0, 1/7) at μ = 1/7 (the definition of the tint), and f0 at μ = 1', () => {
    for (const f0 of [0.5, 0.9, 1])
      for (const tint of [0.6, 0.8, 1]) {
        expect(fresnelF82Tint(f0, tint, F82_MU)).toBeCloseTo(tint * fresnelSchlick(f0, F82_MU), 14);
        expect(fresnelF82Tint(f0, tint, 1)).toBe(f0);
      }
  });

  it('stays in [0, 1] for every f0 and tint, beyond their ranges and at cos θ = 0, 1e-7, 1 + 1e-6', () => {
    const wide = [-0.5, ...grid, 1.5];
    const values = wide.flatMap((f0) =>
      wide.flatMap((tint) => [-0.5, 0, 1e-7, ...mus, 1 + 1e-6].map((mu) => fresnelF82Tint(f0, tint, mu))),
    );
    expect(values.every((f) => f >= 0 && f <= 1)).toBe(true);
  });

  it('clamps where the formula dips below 0 (f0 = tint = 0: −0.127 at its minimum), as its JSDoc says', () => {
    const raw = Math.min(...mus.map((mu) => openPbrF82(0, 0, mu)));
    expect(raw).toBeCloseTo(-0.127, 3);
    expect(Math.min(...mus.map((mu) => fresnelF82Tint(0, 0, mu)))).toBe(0);
  });
});

describe('f82TintFromConductor, fitted to the measured metals (exact conductor Fresnel)', () => {
  it.each(channels)('$name: F82-tint equals the exact conductor at μ = 1 and μ = 1/7', ({ eta, k }) => {
    const { f0, tint } = f82TintFromConductor(eta, k);
    expect(f0).toBeCloseTo(fresnelConductor(1, eta, k), 15);
    expect(fresnelF82Tint(f0, tint, 1)).toBeCloseTo(fresnelConductor(1, eta, k), 14);
    expect(fresnelF82Tint(f0, tint, F82_MU)).toBeCloseTo(fresnelConductor(F82_MU, eta, k), 14);
  });

  it('gives every channel of the talk’s five metals a tint in [0.75, 1): their curves dip below Schlick’s', () => {
    for (const { eta, k } of channels) {
      const { tint } = f82TintFromConductor(eta, k);
      expect(tint).toBeGreaterThan(0.75);
      expect(tint).toBeLessThan(1);
    }
  });

  it('is closer to the exact curve than Schlick (same f0) for every channel of the five metals', () => {
    const maxError = (fn, eta, k) => Math.max(...mus.map((mu) => Math.abs(fn(mu) - fresnelConductor(mu, eta, k))));
    for (const { eta, k } of channels) {
      const { f0, tint } = f82TintFromConductor(eta, k);
      const schlick = maxError((mu) => fresnelSchlick(f0, mu), eta, k);
      const f82 = maxError((mu) => fresnelF82Tint(f0, tint, mu), eta, k);
      expect(f82).toBeLessThan(schlick);
      expect(f82).toBeLessThan(0.025); // iron, the worst, 0.019 (Schlick: 0.18)
    }
  });
});

describe('the catalogue entry', () => {
  it('evaluates the same function with the family’s calling convention (c, params)', () => {
    const entry = FRESNEL_FAMILY.terms.f82Tint;
    expect(entry.js).toBe(fresnelF82Tint);
    expect(entry.evaluate(0.3, { f0: 0.9, tint: 0.8 })).toBe(fresnelF82Tint(0.9, 0.8, 0.3));
    expect(entry.args).toEqual(['f0', 'tint', 'cos']);
  });
});

describe('the Fresnel page’s comparison (src/widgets/metal-fresnel/model.js), recomputed here from src/math', () => {
  const angles = angleGrid();
  const rows = errorTable(angles);
  const worstOf = (fn, eta, k) =>
    Math.max(
      ...angles.map((deg) =>
        Math.abs(fn(Math.cos((deg * Math.PI) / 180)) - fresnelConductor(Math.cos((deg * Math.PI) / 180), eta, k)),
      ),
    );

  it('has the five metals’ fifteen channels, with each model’s worst error over 0–90° as computed directly', () => {
    expect(rows).toHaveLength(15);
    rows.forEach((r, i) => {
      const { eta, k } = channels[i];
      const { f0, tint } = f82TintFromConductor(eta, k);
      expect(Math.abs(r.worst.schlick.value)).toBe(worstOf((mu) => fresnelSchlick(f0, mu), eta, k));
      expect(Math.abs(r.worst.f82Tint.value)).toBe(worstOf((mu) => fresnelF82Tint(f0, tint, mu), eta, k));
      const ior = conductorIorFromF0EdgeTint(f0, edgeTintFromConductorIor(eta, k));
      expect(Math.abs(r.worst.gulbrandsen.value)).toBe(worstOf((mu) => fresnelConductor(mu, ...ior), eta, k));
    });
  });

  it('Gulbrandsen’s (F0, g) round trip is the exact curve to rounding (< 1e-13), as the page says', () => {
    expect(Math.max(...rows.map((r) => Math.abs(r.worst.gulbrandsen.value)))).toBeLessThan(1e-13);
  });
});
