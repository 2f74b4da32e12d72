import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  conductorIorFromF0EdgeTint,
  edgeTintFromConductorIor,
  f0FromIor,
  fresnelConductor,
  fresnelDielectric,
  fresnelSchlick,
  iorFromF0,
} from '../../src/math/fresnel.js';
import { METALS, NON_METALS, channelIor, fresnelParams } from '../../src/math/materials.js';
import { MEASURED_NK, measuredRgbNk, nkAtWavelength } from '../../src/math/optical-constants.js';

const cosDeg = (d) => Math.cos((d * Math.PI) / 180);

// Textbook form with explicit angles (Snell + the s and p amplitude coefficients), as an independent check.
function fresnelTextbook(thetaI, eta) {
  const sinT = Math.sin(thetaI) / eta;
  if (sinT >= 1) return 1;
  const ci = Math.cos(thetaI);
  const ct = Math.sqrt(1 - sinT * sinT);
  const rs = (ci - eta * ct) / (ci + eta * ct);
  const rp = (eta * ci - ct) / (eta * ci + ct);
  return (rs * rs + rp * rp) / 2;
}

describe('fresnelDielectric', () => {
  it('is ((eta-1)/(eta+1))^2 at normal incidence', () => {
    for (const eta of [0.5, 1.33, 1.5, 2.42, 4])
      expect(fresnelDielectric(1, eta)).toBeCloseTo(((eta - 1) / (eta + 1)) ** 2, 14);
  });
  it('matches the textbook Snell form over all angles', () => {
    for (const eta of [1 / 1.5, 1.33, 1.5, 2.42]) {
      for (let d = 0; d < 90; d += 0.5)
        expect(fresnelDielectric(cosDeg(d), eta)).toBeCloseTo(fresnelTextbook((d * Math.PI) / 180, eta), 12);
    }
  });
  it('goes to 1 at grazing incidence', () => {
    for (const eta of [1.0001, 1.33, 1.5, 4]) expect(fresnelDielectric(0, eta)).toBeCloseTo(1, 12);
  });
  it('gives total internal reflection beyond the critical angle', () => {
    const eta = 1 / 1.5;
    const critical = Math.asin(eta) * (180 / Math.PI);
    expect(fresnelDielectric(cosDeg(critical + 0.1), eta)).toBe(1);
    expect(fresnelDielectric(cosDeg(critical - 1), eta)).toBeLessThan(1);
  });
  it('stays accurate as eta -> 1 (no cancellation): F ~ ((eta-1)/2)^2 at normal incidence', () => {
    const eta = 1 + 1e-6;
    expect(fresnelDielectric(1, eta) / ((eta - 1) / (eta + 1)) ** 2).toBeCloseTo(1, 9);
    expect(fresnelDielectric(0.5, 1)).toBe(0);
  });
  it('has Brewster zero of the p-polarisation: F = rs²/2 at tan(theta) = eta', () => {
    const eta = 1.5;
    const c = Math.cos(Math.atan(eta));
    const ct = Math.sqrt(1 - (1 - c * c) / (eta * eta));
    const rs = (c - eta * ct) / (c + eta * ct);
    expect(fresnelDielectric(c, eta)).toBeCloseTo((rs * rs) / 2, 14);
  });
});

describe('fresnelConductor', () => {
  it('reduces to the dielectric when k = 0, total internal reflection included', () => {
    for (const eta of [1 / 1.5, 0.9, 1 + 1e-6, 1.33, 1.5, 2.42, 100]) {
      for (let d = 0; d <= 90; d += 0.25)
        expect(fresnelConductor(cosDeg(d), eta, 0)).toBeCloseTo(fresnelDielectric(cosDeg(d), eta), 12);
    }
  });
  it('equals f0FromIor at normal incidence and 1 at grazing', () => {
    for (const [n, k] of [
      [0.27, 2.78],
      [1.5, 7.7],
      [0.05, 4.4],
      [2.9, 3.1],
    ]) {
      expect(fresnelConductor(1, n, k)).toBeCloseTo(f0FromIor(n, k), 14);
      expect(fresnelConductor(0, n, k)).toBeCloseTo(1, 14);
    }
  });
  it('matches a direct complex-arithmetic evaluation of the Fresnel equations', () => {
    // r_s = (cos i - N cos t)/(cos i + N cos t), r_p = (N cos i - cos t)/(N cos i + cos t), N = n + ik.
    const cx = (re, im) => ({ re, im });
    const mul = (a, b) => cx(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re);
    const add = (a, b) => cx(a.re + b.re, a.im + b.im);
    const sub = (a, b) => cx(a.re - b.re, a.im - b.im);
    const div = (a, b) => {
      const d = b.re * b.re + b.im * b.im;
      return cx((a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d);
    };
    const sqrt = (a) => {
      const r = Math.hypot(a.re, a.im);
      return cx(Math.sqrt((r + a.re) / 2), Math.sign(a.im || 1) * Math.sqrt((r - a.re) / 2));
    };
    const abs2 = (a) => a.re * a.re + a.im * a.im;
    for (const [n, k] of [
      [0.27, 2.78],
      [1.5, 7.7],
      [2.9, 3.1],
      [1.2, 0.3],
    ]) {
      const N = cx(n, k);
      for (let d = 0; d < 90; d += 3) {
        const ci = cosDeg(d);
        const s2 = 1 - ci * ci;
        const ct = sqrt(sub(cx(1, 0), div(cx(s2, 0), mul(N, N))));
        const rs = div(sub(cx(ci, 0), mul(N, ct)), add(cx(ci, 0), mul(N, ct)));
        const rp = div(sub(mul(N, cx(ci, 0)), ct), add(mul(N, cx(ci, 0)), ct));
        expect(fresnelConductor(ci, n, k)).toBeCloseTo((abs2(rs) + abs2(rp)) / 2, 12);
      }
    }
  });
});

describe('Schlick', () => {
  it('is exact at 0° and 90°, close below 45° and within 0.08 overall for the talk’s non-metals', () => {
    for (const m of NON_METALS) {
      const eta = iorFromF0(m.linear[0]);
      expect(fresnelSchlick(m.linear[0], 1)).toBe(m.linear[0]);
      expect(fresnelSchlick(m.linear[0], 0)).toBe(1);
      for (let d = 0; d <= 90; d += 0.5) {
        const err = Math.abs(fresnelSchlick(f0FromIor(eta), cosDeg(d)) - fresnelDielectric(cosDeg(d), eta));
        expect(err).toBeLessThan(d <= 45 ? 0.01 : 0.08);
      }
    }
  });
  it(
    'errs most at grazing angles: metals 72.8°–84.5°, the far-off ones around acos(1/7) ≈ 81.8°, the peak of ' +
      'Hoffman 2019’s error model ("Fresnel Equations Considered Harmful")',
    () => {
      // Hoffman models Schlick's error with the term cos(1 - cos)^6, which peaks at cos = 1/7.
      const peaks = [];
      const curves = [
        ...NON_METALS.map((m) => ({
          name: m.name,
          f: (c) => fresnelDielectric(c, iorFromF0(m.linear[0])),
          f0: m.linear[0],
        })),
        ...METALS.flatMap((m) =>
          measuredRgbNk(m.key).map(([n, k], ch) => ({
            name: `${m.name} ${ch}`,
            f: (c) => fresnelConductor(c, n, k),
            f0: f0FromIor(n, k),
          })),
        ),
      ];
      for (const { name, f, f0 } of curves) {
        let worst = 0;
        let at = 0;
        for (let d = 0; d <= 90; d += 0.05) {
          const e = Math.abs(fresnelSchlick(f0, cosDeg(d)) - f(cosDeg(d)));
          if (e > worst) [worst, at] = [e, d];
        }
        peaks.push({ name, at, worst, metal: !NON_METALS.some((m) => m.name === name) });
      }
      for (const { name, at } of peaks) {
        expect(at, name).toBeGreaterThan(70);
        expect(at, name).toBeLessThan(88);
      }
      // the talk's non-metals (as README states): from 83.8° (water) to 85.4° (Glass (High) / Ruby)
      const nonMetal = Object.fromEntries(peaks.filter((p) => !p.metal).map((p) => [p.name, p.at]));
      expect(Math.abs(nonMetal.Water - 83.78)).toBeLessThan(0.06); // README: 83.8°
      expect(Math.abs(nonMetal['Glass (High) / Ruby'] - 85.44)).toBeLessThan(0.06); // README: 85.4°
      expect(Math.min(...Object.values(nonMetal))).toBe(nonMetal.Water);
      expect(Math.max(...Object.values(nonMetal))).toBe(nonMetal['Glass (High) / Ruby']);
      // Metals where Schlick is noticeably off (> 0.02) peak around 81.8°.
      const metalPeaks = peaks.filter((p) => p.metal && p.worst > 0.02).map((p) => p.at);
      expect(metalPeaks.length).toBeGreaterThanOrEqual(6);
      const mean = metalPeaks.reduce((a, b) => a + b, 0) / metalPeaks.length;
      expect(Math.abs(mean - (Math.acos(1 / 7) * 180) / Math.PI)).toBeLessThan(1.5);
      // docs/math-api.md quotes the measured maxima (to the 0.05° grid), and 1/7 as the error model's peak
      const doc = readFileSync(new URL('../../docs/math-api.md', import.meta.url), 'utf8').replace(/\s+/g, ' ');
      const m = doc.match(
        /between ([\d.]+)° \(silver, blue\) and ([\d.]+)° \(gold, blue\) for the red, green and blue/,
      );
      expect(m).not.toBeNull();
      const metal = peaks.filter((p) => p.metal);
      const close = (quoted, x) => expect(Math.abs(Number(quoted) - x)).toBeLessThanOrEqual(0.06);
      close(m[1], Math.min(...metal.map((p) => p.at)));
      close(m[2], Math.max(...metal.map((p) => p.at)));
      expect(metal.find((p) => p.at === Math.min(...metal.map((q) => q.at))).name).toBe('Silver 2');
      expect(metal.find((p) => p.at === Math.max(...metal.map((q) => q.at))).name).toBe('Gold 2');
      const far = doc.match(
        /cos θ \(1 − cos θ\)⁶, which peaks at cos θ = 1\/7 \(θ ≈ ([\d.]+)°\).*?between ([\d.]+)° and ([\d.]+)°/,
      );
      expect(far).not.toBeNull();
      close(far[1], (Math.acos(1 / 7) * 180) / Math.PI);
      // cos(1 − cos)⁶ peaks at 1/7: its derivative (1 − c)⁵ (1 − 7c) vanishes there
      const model = (c) => c * (1 - c) ** 6;
      expect(model(1 / 7)).toBeGreaterThan(Math.max(model(1 / 7 - 1e-4), model(1 / 7 + 1e-4)));
      const farNames = new Set(peaks.filter((p) => p.metal && p.worst > 0.02).map((p) => p.name.split(' ')[0]));
      expect([...farNames]).toEqual(['Copper', 'Iron', 'Aluminum']); // "copper, iron and aluminium"
      close(far[2], Math.min(...metalPeaks));
      close(far[3], Math.max(...metalPeaks));
    },
  );
});

describe('conductor (n, k) from F0 and edge tint (Gulbrandsen 2014)', () => {
  it('reproduces F0 exactly and round-trips the edge tint', () => {
    for (const r of [0.02, 0.29, 0.56, 0.91, 0.95]) {
      for (const g of [0, 0.3, 0.7, 1]) {
        const [n, k] = conductorIorFromF0EdgeTint(r, g);
        expect(f0FromIor(n, k)).toBeCloseTo(r, 12);
        expect(edgeTintFromConductorIor(n, k)).toBeCloseTo(g, 9);
      }
    }
  });
  it("gives the metals the talk's F0 in 'f0-tint' mode", () => {
    for (const m of METALS) {
      fresnelParams(m.key, 'f0-tint').f0.forEach((f0, i) => expect(f0).toBeCloseTo(Math.min(m.linear[i], 0.999), 9));
    }
  });
});

describe('measured optical constants', () => {
  it('interpolates the published rows', () => {
    const rows = MEASURED_NK.gold.rows;
    expect(nkAtWavelength(rows, 0.5486)).toEqual([0.43, 2.455]);
    const [n] = nkAtWavelength(rows, (0.5209 + 0.5486) / 2);
    expect(n).toBeCloseTo((0.62 + 0.43) / 2, 12);
  });
  it("differ from the talk's F0 by at most ~0.12 (the difference the curves widget shows)", () => {
    for (const m of METALS) {
      channelIor(m.key, 'measured').forEach(([n, k], i) =>
        expect(Math.abs(f0FromIor(n, k) - m.linear[i])).toBeLessThan(0.12),
      );
    }
  });
});
