import { describe, expect, it } from 'vitest';
import {
  abcNormalization,
  beckmannAlphaFromBlinnPhongExponent,
  blinnPhongExponentFromBeckmannAlpha,
  ndfABC,
  ndfBeckmann,
  ndfBlinnPhong,
  ndfBlinnPhongFromSin2,
  ndfGGX,
  ndfSGD,
} from '../../src/math/ndf.js';
import { integrate } from '../../src/math/quadrature.js';
import { matchNdfWidths, ndfHalfWidthDeg } from '../../src/math/ndf-width.js';
import * as V from '../../src/math/visibility.js';
import { erf, erfc } from '../../src/math/special.js';
import { projectedNdfIntegral as projectedIntegral } from '../support/integration-helpers.js';

const { visibilitySmithGGXCorrelated } = V;
const cosGrid = [1e-7, 1e-4, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99, 1];
const alphas = [1e-3, 0.01, 0.05, 0.1, 0.3, 0.6, 1];

describe('every NDF is a normalised density: ∫ D (n·m) dω = 1', () => {
  const cases = [
    ...[0.02, 0.05, 0.1, 0.3, 0.6, 1].flatMap((a) => [
      [`GGX α=${a}`, (c) => ndfGGX(c, a)],
      [`Beckmann α=${a}`, (c) => ndfBeckmann(c, a)],
    ]),
    ...[0, 1, 10, 100, 1e4, 1e6].map((p) => [`Blinn-Phong p=${p}`, (c) => ndfBlinnPhong(c, p)]),
    ...[
      [0.01, 1],
      [0.5, 20],
      [1, 1],
      [1, 2],
      [10, 2.5],
      [100, 1.5],
      [1e4, 3],
      [50, 0.5],
      [5, 10],
    ].map(([a1, a2]) => [`ABC ${a1},${a2}`, (c) => ndfABC(c, a1, a2)]),
    ...[
      [0.01, 0.5],
      [0.05, 0.64],
      [0.1, 1],
      [0.3, 1.5],
      [1, 0],
      [2, 1.9],
      [0.5, 1.9],
    ].map(([a, p]) => [`SGD ${a},${p}`, (c) => ndfSGD(c, a, p)]),
  ];
  for (const [name, D] of cases) {
    it(name, () => expect(Math.abs(projectedIntegral(D) - 1)).toBeLessThan(1e-5));
  }
  it('the ABC normalisation: series and closed form agree where both hold', () => {
    // at a1 (a2 + 1) = 1 the code switches; just either side the two must agree
    for (const a2 of [0.5, 1, 2, 4]) {
      const a1 = 1 / (a2 + 1);
      expect(abcNormalization(a1 * (1 - 1e-9), a2)).toBeCloseTo(abcNormalization(a1 * (1 + 1e-9), a2), 9);
    }
  });
});

describe('Blinn-Phong for any exponent a double holds', () => {
  // 2π ∫ D cos θ sin θ dθ in t = θ/w, w = sqrt(2/p) the lobe's width: Gauss-Kronrod on [0, 12] (e^-72 beyond)
  const overTheta = (D, p) => {
    const w = Math.sqrt(2 / p);
    const [c, s] = [(t) => Math.cos(w * t), (t) => Math.sin(w * t)];
    return integrate((t) => 2 * Math.PI * D(c(t), s(t) ** 2) * c(t) * s(t) * w, 0, 12, 1e-12);
  };
  it.each([2e8, 1e12, 1e20, 1e100, 1e300])('from sin²θm, p = %d: ∫ D (n·m) dω = 1 within 1e-9', (p) => {
    expect(Math.abs(overTheta((c, s2) => ndfBlinnPhongFromSin2(c, s2, p), p) - 1)).toBeLessThan(1e-9);
  });
  it("from n·m alone, Walter's p = 2e8 (alpha = 1e-4) and 1e10 stay normalised within 1e-5", () => {
    for (const p of [blinnPhongExponentFromBeckmannAlpha(1e-4), 1e10]) {
      expect(Math.abs(overTheta((c) => ndfBlinnPhong(c, p), p) - 1)).toBeLessThan(1e-5);
      expect(Math.abs(projectedIntegral((c) => ndfBlinnPhong(c, p)) - 1)).toBeLessThan(1e-5);
    }
  });
  it('gives finite values for the largest double and Infinity: the peak (p + 2)/2π, 0 off it, never NaN', () => {
    for (const p of [Number.MAX_VALUE, Infinity]) {
      expect(ndfBlinnPhong(1, p)).toBeCloseTo(Number.MAX_VALUE / (2 * Math.PI), -300);
      expect(Number.isFinite(ndfBlinnPhong(1, p))).toBe(true);
      expect(ndfBlinnPhong(1 - 1e-16, p)).toBe(0);
      expect(ndfBlinnPhongFromSin2(1, 1e-300, p)).toBe(0);
    }
    expect(ndfBlinnPhong(1e-9, 0)).toBeCloseTo(1 / Math.PI, 12); // p = 0 at a grazing normal: no 0·Inf
  });
});

describe('NDF widths', () => {
  it('Blinn-Phong ↔ Beckmann (Walter 2007): p = 2/α² - 2 and back', () => {
    for (const a of [0.05, 0.2, 0.5])
      expect(beckmannAlphaFromBlinnPhongExponent(blinnPhongExponentFromBeckmannAlpha(a))).toBeCloseTo(a, 12);
    // the matched pair has nearly the same lobe: peak values within 1% for small alpha
    const a = 0.1;
    expect(ndfBlinnPhong(1, blinnPhongExponentFromBeckmannAlpha(a)) / ndfBeckmann(1, a)).toBeCloseTo(1, 2);
  });
  it('matched widths give all five NDFs the same half width at half maximum', () => {
    for (const hw of [2, 10, 30]) {
      const m = matchNdfWidths(hw);
      const widths = [
        ndfHalfWidthDeg((c) => ndfGGX(c, m.ggx.alpha)),
        ndfHalfWidthDeg((c) => ndfBeckmann(c, m.beckmann.alpha)),
        ndfHalfWidthDeg((c) => ndfBlinnPhong(c, m.blinnPhong.exponent)),
        ndfHalfWidthDeg((c) => ndfABC(c, m.abc.a1, m.abc.a2)),
        ndfHalfWidthDeg((c) => ndfSGD(c, m.sgd.alpha, m.sgd.p)),
      ];
      for (const w of widths) expect(w).toBeCloseTo(hw, 3);
    }
  });
  it('at matched width, GGX has the longer tail than Beckmann (the halo of spiky NDFs)', () => {
    const m = matchNdfWidths(5);
    const at = Math.cos((30 * Math.PI) / 180);
    expect(ndfGGX(at, m.ggx.alpha)).toBeGreaterThan(100 * ndfBeckmann(at, m.beckmann.alpha));
  });
});

describe('special functions', () => {
  it('erf and erfc match published values', () => {
    expect(erf(0.5)).toBeCloseTo(0.5204998778130465, 15);
    expect(erf(1)).toBeCloseTo(0.8427007929497149, 15);
    expect(erf(2)).toBeCloseTo(0.9953222650189527, 14);
    expect(erfc(3) / 2.209049699858544e-5).toBeCloseTo(1, 12);
    expect(erfc(5) / 1.5374597944280349e-12).toBeCloseTo(1, 12);
    expect(erf(-1)).toBeCloseTo(-0.8427007929497149, 15);
  });
});

describe('Smith G1', () => {
  it('stays in [0, 1], is 1 at normal incidence and 0 at grazing', () => {
    for (const G1 of [V.smithG1GGX, V.smithG1Beckmann, V.smithG1BeckmannWalter]) {
      for (const a of alphas) {
        for (const c of cosGrid) {
          const g = G1(c, a);
          expect(g).toBeGreaterThanOrEqual(0);
          expect(g).toBeLessThanOrEqual(1);
        }
        expect(G1(1, a)).toBe(1);
        expect(G1(0, a)).toBe(0);
      }
    }
  });
  it("Beckmann's exact G1 matches 1/(1 + Λ) with Λ by numerical integration of the slope distribution", () => {
    // Λ(μ) = ∫ (q - cot θ) P(q) dq over q > cot θ, P the 1-D Beckmann slope density (Heitz 2014, eq. 72)
    for (const a of [0.2, 0.5]) {
      for (const c of [0.2, 0.5, 0.8]) {
        const cot = c / Math.sqrt(1 - c * c);
        let lambda = 0;
        const n = 200000;
        const top = cot + 12 * a;
        for (let i = 0; i < n; i++) {
          const q = cot + ((i + 0.5) * (top - cot)) / n;
          lambda += ((q - cot) * Math.exp(-(q * q) / (a * a))) / (a * Math.sqrt(Math.PI));
        }
        lambda = (lambda * (top - cot)) / n / cot;
        expect(V.smithG1Beckmann(c, a)).toBeCloseTo(1 / (1 + lambda), 6);
      }
    }
  });
  it("Walter's rational fit stays within 0.4% of the exact Beckmann G1", () => {
    for (const a of alphas)
      for (const c of cosGrid)
        expect(Math.abs(V.smithG1BeckmannWalter(c, a) - V.smithG1Beckmann(c, a))).toBeLessThan(4e-3);
  });
});

describe('visibility terms', () => {
  it('separable Smith ≤ height-correlated (it counts shared shadowing twice)', () => {
    for (const a of alphas) {
      for (const nl of cosGrid) {
        for (const nv of cosGrid) {
          expect(V.visibilitySmithGGXSeparable(nl, nv, a)).toBeLessThanOrEqual(
            visibilitySmithGGXCorrelated(nl, nv, a) * (1 + 1e-12),
          );
        }
      }
    }
  });
  it('the separable form is G1(l) G1(v) / ((n·l)(n·v))', () => {
    for (const a of [0.1, 0.5])
      for (const [nl, nv] of [
        [0.3, 0.9],
        [0.7, 0.2],
      ]) {
        expect(V.visibilitySmithGGXSeparable(nl, nv, a)).toBeCloseTo(
          (V.smithG1GGX(nl, a) * V.smithG1GGX(nv, a)) / (nl * nv),
          12,
        );
      }
  });
  it('the implicit term ignores roughness and the Cook-Torrance G stays in [0, 1]', () => {
    expect(V.visibilityImplicit(0.3, 0.4)).toBe(1);
    for (const nl of cosGrid)
      for (const nv of cosGrid)
        for (const nh of [0.5, 0.9, 1])
          for (const vh of [0.2, 0.7, 1]) {
            const G = V.visibilityCookTorrance(nl, nv, nh, vh) * nl * nv;
            expect(G).toBeGreaterThanOrEqual(0);
            expect(G).toBeLessThanOrEqual(1 + 1e-12);
          }
  });
  it("Kelemen's 1/(l·h)² tracks Cook-Torrance where Cook-Torrance's G is 1", () => {
    // with l = v = n: G_ct = 1, V_ct = 1/(nl nv) = 1 = 1/(l·h)²
    expect(V.visibilityKelemen(1)).toBe(V.visibilityCookTorrance(1, 1, 1, 1));
  });
  it('the cheap approximations equal height-correlated Smith head-on and stay within 20% for cos >= 0.4', () => {
    // measured: Hammon at most 16.3% off (alpha 0.3, nl = nv = 0.4), Schlick-GGX 19.1% (alpha 0.6)
    for (const a of [0.1, 0.3, 0.6]) {
      expect(V.visibilitySmithGGXCorrelatedFast(1, 1, a)).toBeCloseTo(visibilitySmithGGXCorrelated(1, 1, a), 12);
      expect(V.visibilitySchlickGGX(1, 1, a)).toBeCloseTo(visibilitySmithGGXCorrelated(1, 1, a), 12);
      for (const nl of [0.4, 0.7, 1])
        for (const nv of [0.4, 0.7, 1]) {
          const ref = visibilitySmithGGXCorrelated(nl, nv, a);
          expect(Math.abs(V.visibilitySmithGGXCorrelatedFast(nl, nv, a) / ref - 1)).toBeLessThan(0.2);
          expect(Math.abs(V.visibilitySchlickGGX(nl, nv, a) / ref - 1)).toBeLessThan(0.2);
        }
    }
  });
  it('every V is 0 below the horizon and finite above it, down to cos = 1e-7 and alpha = 0', () => {
    const fns = [
      V.visibilitySmithGGXSeparable,
      V.visibilitySmithGGXCorrelated,
      V.visibilitySmithGGXCorrelatedFast,
      V.visibilitySchlickGGX,
      V.visibilitySmithBeckmannSeparable,
    ];
    for (const f of fns) {
      expect(f(-0.1, 0.5, 0.3)).toBe(0);
      expect(f(0.5, 0, 0.3)).toBe(0);
      for (const a of [0, 1e-5, 1]) for (const c of [1e-7, 0.5, 1]) expect(Number.isFinite(f(c, c, a))).toBe(true);
    }
  });
});

describe('ndfGGX', () => {
  it('is normalised: ∫ D (n·m) dω = 1 across roughness', () => {
    for (const a of [0.01, 0.05, 0.1, 0.3, 0.6, 1]) expect(projectedIntegral((c) => ndfGGX(c, a))).toBeCloseTo(1, 3);
  });
  it('equals the textbook form where that form is well conditioned', () => {
    const textbook = (c, a) => (a * a) / (Math.PI * (c * c * (a * a - 1) + 1) ** 2);
    for (const a of [0.1, 0.5, 1])
      for (const c of [0.1, 0.5, 0.9, 1]) expect(ndfGGX(c, a)).toBeCloseTo(textbook(c, a), 10);
  });
  it('peaks at 1/(pi alpha²) and stays finite down to alpha = 1e-4 (and alpha = 0 is clamped)', () => {
    expect(ndfGGX(1, 1e-4)).toBeCloseTo(1 / (Math.PI * 1e-8), -2);
    expect(Number.isFinite(ndfGGX(1, 0))).toBe(true);
    expect(ndfGGX(0, 0.5)).toBe(0);
    expect(ndfGGX(-0.3, 0.5)).toBe(0);
  });
  it('keeps its float32 value at c = 1 where the textbook denominator cancels', () => {
    const f = Math.fround;
    for (const a of [1e-4, 3e-4]) {
      const c = 1;
      // textbook in float32: a² - 1 rounds to -1 (or nearly), so c²(a² - 1) + 1 is 0 (D = Inf) or far off
      const den32 = f(f(f(c * c) * f(f(a * a) - 1)) + 1);
      const textbook32 = f(a * a) / f(Math.PI * f(den32 * den32));
      expect(Math.abs(textbook32 - ndfGGX(c, a)) / ndfGGX(c, a)).toBeGreaterThan(0.2);
      // the stable form, evaluated step by step in float32, keeps 1/(pi a²)
      const d32 = f(f(f(a * a) * f(c * c)) + f(f(1 - c) * f(1 + c)));
      const t32 = f(a / d32);
      expect(Math.abs(f(t32 * t32) / Math.PI - ndfGGX(c, a)) / ndfGGX(c, a)).toBeLessThan(1e-6);
    }
  });
});

describe('visibilitySmithGGXCorrelated', () => {
  it('matches Heitz 2014 G2 = 1 / (1 + Λ(l) + Λ(v)) divided by (n·l)(n·v)', () => {
    const lambda = (c, a) => (-1 + Math.sqrt(1 + (a * a * (1 - c * c)) / (c * c))) / 2;
    for (const a of [0.05, 0.3, 1]) {
      for (const nl of [0.05, 0.4, 1]) {
        for (const nv of [0.1, 0.7, 1]) {
          const G = 1 / (1 + lambda(nl, a) + lambda(nv, a));
          expect(visibilitySmithGGXCorrelated(nl, nv, a)).toBeCloseTo(G / (nl * nv), 10);
        }
      }
    }
  });
  it('is 0 at and below the horizon and never NaN or Inf in its domain', () => {
    expect(visibilitySmithGGXCorrelated(0, 0.5, 0.3)).toBe(0);
    expect(visibilitySmithGGXCorrelated(0.5, -0.1, 0.3)).toBe(0);
    for (const a of [0, 1e-5, 1e-4, 1])
      for (const c of [1e-7, 1e-4, 1]) expect(Number.isFinite(visibilitySmithGGXCorrelated(c, c, a))).toBe(true);
  });
});
