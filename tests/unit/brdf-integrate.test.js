import { describe, expect, it } from 'vitest';
import {
  brdf,
  brdfFromPunctualRadiance,
  microfacetBRDF,
  punctualRadiance,
  VISIBILITY_TERMS,
  NDF_TERMS,
} from '../../src/math/brdf.js';
import { albedoGGX, directionFromCos, hemisphereIntegral, reflectanceImportanceGGX } from '../../src/math/integrate.js';
import { fresnelSchlick } from '../../src/math/fresnel.js';

const dir = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
const base = {
  F: 'schlick',
  D: 'ggx',
  V: 'smithGGXCorrelated',
  f0: 0.04,
  alpha: 0.3,
  exponent: 40,
  a1: 20,
  a2: 2.5,
  p: 0.64,
  eta: 1.5,
  k: 0,
};

describe('microfacet BRDF', () => {
  it('is reciprocal: f(l, v) = f(v, l) for every term combination', () => {
    for (const D of Object.keys(NDF_TERMS)) {
      for (const V of Object.keys(VISIBILITY_TERMS)) {
        const p = { ...base, D, V };
        for (const [l, v] of [
          [dir(0.3, 0), dir(1.1, 2)],
          [dir(1.4, 1), dir(0.2, -1)],
          [dir(0.8, 0.5), dir(0.8, 0.5 + Math.PI)],
        ]) {
          expect(microfacetBRDF(l, v, p)).toBeCloseTo(microfacetBRDF(v, l, p), 10);
        }
      }
    }
  });
  it('gives the same value from the cosines alone (as a probe reads them) as from the vectors', async () => {
    const { microfacetBRDFAt, brdfAngles } = await import('../../src/math/brdf.js');
    for (const [l, v] of [
      [dir(0.3, 0), dir(1.1, 2)],
      [dir(1.4, 1), dir(0.2, -1)],
    ]) {
      const cosines = brdfAngles(l, v);
      delete cosines.h; // from the cosines alone
      expect(microfacetBRDFAt(cosines, base)).toBeCloseTo(microfacetBRDF(l, v, base), 9);
    }
  });
  it('is 0 below the horizon and for l = -v, and never NaN, Inf or negative', () => {
    expect(microfacetBRDF(dir(2, 0), dir(0.3, 0), base)).toBe(0);
    expect(microfacetBRDF([0, 0, 1], [0, 0, -1], base)).toBe(0);
    const grazing = [1, 0, 0];
    for (const p of [base, { ...base, alpha: 1e-4 }, { ...base, alpha: 0 }]) {
      for (const [l, v] of [
        [grazing, grazing],
        [
          [0, 0, 1],
          [0, 0, 1],
        ],
        [grazing, [0, 0, 1]],
        [dir(1.5707, 0), dir(1.5707, Math.PI)],
      ]) {
        const f = brdf(l, v, p);
        expect(Number.isFinite(f) && f >= 0).toBe(true);
      }
    }
  });
  it('is F·D·V/4 with the half-vector angles', () => {
    const l = dir(0.5, 0);
    const v = dir(0.9, Math.PI);
    const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
    const len = Math.hypot(...h);
    const nh = h[2] / len;
    const lh = (l[0] * h[0] + l[2] * h[2]) / len;
    const a2 = 0.09;
    const D = a2 / (Math.PI * (nh * nh * (a2 - 1) + 1) ** 2);
    const lam = (c) => (-1 + Math.sqrt(1 + (a2 * (1 - c * c)) / (c * c))) / 2;
    const V = 1 / (1 + lam(l[2]) + lam(v[2])) / (l[2] * v[2]);
    expect(microfacetBRDF(l, v, base)).toBeCloseTo((fresnelSchlick(0.04, lh) * D * V) / 4, 12);
  });
  it('tends to the mirror as alpha -> 0: all reflected light leaves along the mirror direction', () => {
    // E(mu) -> F(mu) and the lobe's energy concentrates where l = reflect(v, n)
    const p = { ...base, F: 'one', alpha: 1e-3 };
    expect(albedoGGX(0.7, 1e-3)).toBeCloseTo(1, 3);
    const v = dir(0.6, 0);
    const mirror = dir(0.6, Math.PI);
    expect(microfacetBRDF(mirror, v, p)).toBeGreaterThan(1e4 * microfacetBRDF(dir(0.65, Math.PI), v, p));
  });
  it("gives a white Lambertian surface lit head-on exactly c_light with the talk's punctual equation", () => {
    const lambert = () => 1 / Math.PI;
    expect(punctualRadiance(lambert(), 1, 3.5)).toBeCloseTo(3.5, 14);
    expect(punctualRadiance(lambert(), -0.2, 3.5)).toBe(0);
  });
  it('reads the BRDF back from a punctual radiance: white Lambert head-on gives 1/π; no light gives none', () => {
    expect(brdfFromPunctualRadiance(3.5, 1, 3.5)).toBeCloseTo(1 / Math.PI, 15); // L = c_light: the talk's definition
    expect(brdfFromPunctualRadiance(1.5, 0.5, 3)).toBeCloseTo(1 / Math.PI, 15); // c_light cos 60°
    for (const [f, nl, c] of [
      [0.02, 0.3, 2],
      [5, 0.01, 0.7],
      [1e-4, 1, 10],
    ])
      expect(brdfFromPunctualRadiance(punctualRadiance(f, nl, c), nl, c)).toBeCloseTo(f, 12);
    expect(brdfFromPunctualRadiance(0, -0.2, 3)).toBeNull();
    expect(brdfFromPunctualRadiance(0, 0.5, 0)).toBeNull();
  });
});

describe('directional albedo (white furnace, F = 1)', () => {
  it('equals the closed form 1 - ln 2 at alpha = 1, mu = 1', () => {
    // GGX at alpha = 1 is D = 1/pi; with v = n, E = 2 ∫_0^{pi/4} (sin 2θ - tan θ) dθ = 1 - ln 2
    expect(albedoGGX(1, 1)).toBeCloseTo(1 - Math.log(2), 9);
  });
  it('never exceeds 1, falls with roughness, and is 1 for a near-mirror at normal incidence', () => {
    for (const mu of [0.05, 0.3, 0.7, 1]) {
      let prev = 2;
      for (const a of [0.01, 0.2, 0.5, 0.8, 1]) {
        const e = albedoGGX(mu, a);
        expect(e).toBeLessThanOrEqual(1);
        expect(e).toBeLessThan(prev + 1e-9);
        prev = e;
      }
    }
    expect(albedoGGX(1, 0.01)).toBeGreaterThan(0.999);
  });
  it('importance sampling (4096 samples) agrees with the quadrature of the reflectance equation', () => {
    for (const a of [0.4, 0.7, 1]) {
      for (const mu of [0.2, 0.6, 1]) {
        const v = directionFromCos(mu);
        const p = { ...base, F: 'one', alpha: a };
        const sampled = reflectanceImportanceGGX((l) => microfacetBRDF(l, v, p), v, a, 4096);
        expect(sampled).toBeCloseTo(albedoGGX(mu, a), 2);
        expect(hemisphereIntegral((l) => microfacetBRDF(l, v, p), 300)).toBeCloseTo(albedoGGX(mu, a), 2);
      }
    }
  });
  it('importance sampling converges as N grows', () => {
    const v = directionFromCos(0.5);
    const p = { ...base, alpha: 0.5 };
    const f = (l, vv) => microfacetBRDF(l, vv, p);
    const ref = reflectanceImportanceGGX(f, v, 0.5, 1 << 16);
    const errs = [64, 1024, 16384].map((n) => Math.abs(reflectanceImportanceGGX(f, v, 0.5, n) - ref));
    expect(errs[1]).toBeLessThan(errs[0]);
    expect(errs[2]).toBeLessThan(errs[1]);
    expect(errs[2]).toBeLessThan(1e-3);
  });
});

describe('half/difference angles (Rusinkiewicz 1998)', async () => {
  const { directionsFromHalfDiff, halfDiffAngles } = await import('../../src/math/half-diff.js');
  it('round-trips and gives unit directions whose half vector is at theta_h', () => {
    for (const th of [0, 0.3, 1.2])
      for (const td of [0, 0.4, 1.1])
        for (const pd of [0, 1, 2.5]) {
          const { l, v } = directionsFromHalfDiff(th, td, pd);
          expect(Math.hypot(...l)).toBeCloseTo(1, 12);
          expect(Math.hypot(...v)).toBeCloseTo(1, 12);
          const back = halfDiffAngles(l, v);
          expect(back.thetaH).toBeCloseTo(th, 9);
          expect(back.thetaD).toBeCloseTo(td, 9);
        }
  });
  it('theta_h = 0, theta_d = θ is the mirror configuration at θ', () => {
    const { l, v } = directionsFromHalfDiff(0, 0.7, 0);
    expect(l[2]).toBeCloseTo(Math.cos(0.7), 12);
    expect(v[0]).toBeCloseTo(-l[0], 12);
  });
});

describe('2-D microsurface (independent of the Smith formulas it is compared with)', async () => {
  const { generateProfile, measuredG1, sampleSlope, seededRandom } = await import('../../src/math/microsurface.js');
  const { smithG1Beckmann, smithG1GGX } = await import('../../src/math/visibility.js');
  it('draws Beckmann slopes with variance alpha²/2 and GGX slopes with the GGX marginal median alpha/sqrt(3)', () => {
    const rand = seededRandom(11);
    const b = Array.from({ length: 200000 }, () => sampleSlope('beckmann', 0.4, rand));
    expect(b.reduce((s, x) => s + x * x, 0) / b.length).toBeCloseTo(0.08, 3);
    // GGX marginal CDF 1/2 + q/(2 sqrt(a² + q²)) = 3/4 at q = a/sqrt(3)
    const g = Array.from({ length: 200000 }, () => Math.abs(sampleSlope('ggx', 0.4, rand))).sort((x, y) => x - y);
    expect(g[g.length / 2]).toBeCloseTo(0.4 / Math.sqrt(3), 2);
  });
  it("ray-traced shadowing matches Smith's G1 within 0.03", () => {
    for (const [kind, G1] of [
      ['beckmann', smithG1Beckmann],
      ['ggx', smithG1GGX],
    ]) {
      const h = generateProfile(80000, kind, 0.5, 4);
      for (const deg of [30, 60, 75, 85]) {
        const t = (deg * Math.PI) / 180;
        expect(Math.abs(measuredG1(h, t) - G1(Math.cos(t), 0.5))).toBeLessThan(0.03);
      }
    }
  });
});

describe('reflection off a 2-D microsurface', async () => {
  const { generateProfile, reflectedAngleDensity, reflectedAngles, seededRandom } =
    await import('../../src/math/microsurface.js');
  const { smithG1Beckmann, smithG1GGX } = await import('../../src/math/visibility.js');
  it('ray-traced first reflections follow the microfacet prediction (histogram converges)', () => {
    for (const [kind, G1] of [
      ['beckmann', smithG1Beckmann],
      ['ggx', smithG1GGX],
    ]) {
      for (const deg of [20, 60]) {
        const ti = (deg * Math.PI) / 180;
        const h = generateProfile(60000, kind, 0.3, 5);
        const bins = 36;
        const lo = -Math.PI;
        const width = (2 * Math.PI) / bins;
        const hist = (n) => {
          const counts = new Float64Array(bins);
          for (const t of reflectedAngles(h, ti, n, seededRandom(n)))
            counts[Math.min(Math.floor((t - lo) / width), bins - 1)] += 1 / n / width;
          return counts;
        };
        const predicted = Float64Array.from({ length: bins }, (_, b) => {
          let s = 0;
          for (let k = 0; k < 20; k++)
            s += reflectedAngleDensity(lo + (b + (k + 0.5) / 20) * width, ti, kind, 0.3, G1) / 20;
          return s;
        });
        const l1 = (c) => c.reduce((s, x, b) => s + Math.abs(x - predicted[b]) * width, 0);
        const [coarse, fine] = [l1(hist(2000)), l1(hist(40000))];
        expect(fine).toBeLessThan(coarse); // converges as rays are added
        expect(fine, `${kind} ${deg}°`).toBeLessThan(0.06); // to within the Smith approximation
        expect(predicted.reduce((s, x) => s + x * width, 0)).toBeCloseTo(1, 1); // a density
      }
    }
  });
});
