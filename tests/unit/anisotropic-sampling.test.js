// The anisotropic GGX visible-normal sampler (src/math/anisotropic.js) against its density by Pearson's χ² test,
// as Mitsuba 3 checks its samplers (mitsuba.chi2.ChiSquareTest: a histogram of samples against the integral of
// the pdf over each bin, bins with fewer than 5 expected samples pooled, significance 1 % with Šidák's correction
// over the tests run); against Dupuy & Benyoub 2023's listing, of which it is a rearrangement; and at its float edges.
import { describe, expect, it } from 'vitest';
import * as M from '../../src/math/index.js';
import { gaussLegendre } from '../../src/math/quadrature.js';
import { seededRandom } from '../../src/math/microsurface.js';
import { erfc } from '../../src/math/special.js';

const spherical = (theta, phi) => [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];

// Bins over the hemisphere of m: θ = (π/2) s² (crowded near n, where narrow lobes are) in S bins of s, φ in P bins.
const S = 24;
const P = 48;
const binOf = ([x, y, z]) => {
  const theta = Math.atan2(Math.hypot(x, y), z);
  const s = Math.sqrt(theta / (Math.PI / 2));
  const phi = (Math.atan2(y, x) + 2 * Math.PI) % (2 * Math.PI);
  return Math.min(Math.floor(s * S), S - 1) * P + Math.min(Math.floor((phi / (2 * Math.PI)) * P), P - 1);
};

/** N ∫_bin pdf dω for every bin, by 8 × 8 Gauss–Legendre in (s, φ) per bin (dω = sin θ · π s ds dφ). */
function expectedCounts(pdf, n) {
  const { x, w } = gaussLegendre(8);
  const counts = new Float64Array(S * P);
  for (let i = 0; i < S; i++)
    for (let j = 0; j < P; j++) {
      let sum = 0;
      for (let a = 0; a < 8; a++) {
        const s = (i + (1 + x[a]) / 2) / S;
        const theta = (Math.PI / 2) * s * s;
        for (let b = 0; b < 8; b++) {
          const phi = ((j + (1 + x[b]) / 2) / P) * 2 * Math.PI;
          sum += w[a] * w[b] * pdf(spherical(theta, phi)) * Math.sin(theta) * Math.PI * s;
        }
      }
      counts[i * P + j] = n * sum * (1 / S / 2) * ((2 * Math.PI) / P / 2);
    }
  return counts;
}

/** The upper tail of χ² with k degrees of freedom, by Wilson & Hilferty's cube-root normal (k here is ~10³). */
function chi2Tail(chi2, k) {
  const z = ((chi2 / k) ** (1 / 3) - (1 - 2 / (9 * k))) / Math.sqrt(2 / (9 * k));
  return erfc(z / Math.SQRT2) / 2;
}

/** Pearson's χ² of observed against expected counts, bins with fewer than 5 expected pooled (Mitsuba's rule). */
function chi2Test(observed, expected) {
  const order = [...expected.keys()].sort((a, b) => expected[a] - expected[b]);
  let chi2 = 0;
  let dof = -1;
  let [poolObs, poolExp] = [0, 0];
  for (const i of order) {
    if (expected[i] < 5) {
      [poolObs, poolExp] = [poolObs + observed[i], poolExp + expected[i]];
      if (poolExp < 5) continue;
      [chi2, dof, poolObs, poolExp] = [chi2 + (poolObs - poolExp) ** 2 / poolExp, dof + 1, 0, 0];
      continue;
    }
    chi2 += (observed[i] - expected[i]) ** 2 / expected[i];
    dof++;
  }
  if (poolExp > 0) [chi2, dof] = [chi2 + (poolObs - poolExp) ** 2 / Math.max(poolExp, 1e-300), dof + 1];
  return { chi2, dof, p: chi2Tail(chi2, dof) };
}

const SAMPLES = 250_000;
const CONFIGS = [
  { theta: 0, phi: 0, ax: 0.3, ay: 0.3 },
  { theta: 1.2, phi: 0.5, ax: 0.1, ay: 0.5 },
  { theta: 1.5, phi: 2, ax: 0.5, ay: 0.05 },
  { theta: 0.7, phi: -1, ax: 1, ay: 0.2 },
  { theta: 1.55, phi: 0, ax: 0.02, ay: 0.6 },
];
const SIGNIFICANCE = 1 - (1 - 0.01) ** (1 / CONFIGS.length); // Šidák: 1 % over all the tests together

function histogram(v, ax, ay, seed) {
  const rand = seededRandom(seed);
  const observed = new Float64Array(S * P);
  for (let k = 0; k < SAMPLES; k++) observed[binOf(M.sampleVisibleNormalGGXAniso(...v, ax, ay, rand(), rand()))]++;
  return observed;
}

describe('sampleVisibleNormalGGXAniso: the histogram of its normals against visibleNormalPdfGGXAniso (χ²)', () => {
  CONFIGS.forEach(({ theta, phi, ax, ay }, c) => {
    const v = spherical(theta, phi);
    it(`v at θ = ${theta}, φ = ${phi}, α = (${ax}, ${ay}): not rejected at 1 % (Šidák over ${CONFIGS.length})`, () => {
      const observed = histogram(v, ax, ay, 100 + c);
      const expected = expectedCounts((m) => M.visibleNormalPdfGGXAniso(...v, ...m, ax, ay), SAMPLES);
      // the pdf integrates to 1 over the bins (the weak furnace, to the bins' quadrature)
      expect(expected.reduce((s, e) => s + e, 0) / SAMPLES).toBeCloseTo(1, 3);
      const { p, dof, chi2 } = chi2Test(observed, expected);
      console.log(
        `χ² ${chi2.toFixed(1)} on ${dof} degrees of freedom, p = ${p.toFixed(3)} (θ ${theta}, α ${ax}, ${ay})`,
      );
      expect(dof).toBeGreaterThan(100);
      expect(p, `p = ${p.toExponential(2)}`).toBeGreaterThan(SIGNIFICANCE);
    });
  });
  it('rejects the same samples against a wrong density: αx and αy exchanged, or D(m)(n·m) (all normals)', () => {
    const v = spherical(1.2, 0.5);
    const observed = histogram(v, 0.1, 0.5, 101);
    const swapped = expectedCounts((m) => M.visibleNormalPdfGGXAniso(...v, ...m, 0.5, 0.1), SAMPLES);
    const allNormals = expectedCounts((m) => M.ndfGGXAniso(...m, 0.1, 0.5) * m[2], SAMPLES);
    expect(chi2Test(observed, swapped).p).toBeLessThan(1e-12);
    expect(chi2Test(observed, allNormals).p).toBeLessThan(1e-12);
  });
});

/** Dupuy & Benyoub 2023, listing 3 as printed (z = (1 - u1)(1 + w) - w; sin from 1 - z²; h = c + wi, unstretched). */
function listing(v, ax, ay, u1, u2) {
  const s = [ax * v[0], ay * v[1], v[2]];
  const len = Math.hypot(...s);
  const wi = s.map((x) => x / len);
  const phi = 2 * Math.PI * u2;
  const z = (1 - u1) * (1 + wi[2]) - wi[2];
  const sinTheta = Math.sqrt(Math.min(Math.max(1 - z * z, 0), 1));
  const h = [sinTheta * Math.cos(phi) + wi[0], sinTheta * Math.sin(phi) + wi[1], z + wi[2]];
  const m = [ax * h[0], ay * h[1], h[2]];
  const ml = Math.hypot(...m);
  return m.map((x) => x / ml);
}

describe('sampleVisibleNormalGGXAniso: Dupuy & Benyoub 2023’s listing, rearranged for float32', () => {
  const rand = seededRandom(7);
  it('gives the listing’s normal (within 1e-12, its azimuth turned to the view’s) away from the cap’s rim', () => {
    for (let k = 0; k < 2000; k++) {
      const v = spherical(Math.acos(rand()), 2 * Math.PI * rand());
      const [ax, ay] = [10 ** (-2 * rand()), 10 ** (-2 * rand())];
      const [u1, u2] = [0.98 * rand(), rand()];
      const got = M.sampleVisibleNormalGGXAniso(...v, ax, ay, u1, u2);
      // the listing's azimuth is from t, this one's from the stretched view's azimuth
      const offset = Math.atan2(ay * v[1], ax * v[0]) / (2 * Math.PI);
      const want = listing(v, ax, ay, u1, u2 + offset);
      for (let i = 0; i < 3; i++) expect(Math.abs(got[i] - want[i])).toBeLessThan(1e-12);
    }
  });
  it('keeps a unit, visible normal with hz >= 0 at the stress inputs (αx = 1e-4, grazing v, u1 = 1 - 1e-9)', () => {
    const views = [[0, 0, 1], spherical(Math.PI / 2 - 1e-7, 0), spherical(Math.PI / 2 - 1e-7, Math.PI / 2)];
    for (const v of views)
      for (const [ax, ay] of [
        [1e-4, 1],
        [1, 1e-4],
        [1e-4, 1e-4],
      ])
        for (const u1 of [0, 1e-9, 0.5, 1 - 1e-9])
          for (const u2 of [0, 0.25, 0.5, 0.75]) {
            const m = M.sampleVisibleNormalGGXAniso(...v, ax, ay, u1, u2);
            expect(Math.abs(Math.hypot(...m) - 1)).toBeLessThan(1e-15);
            expect(m[2]).toBeGreaterThanOrEqual(0);
            expect(v[0] * m[0] + v[1] * m[1] + v[2] * m[2]).toBeGreaterThanOrEqual(-1e-15);
          }
  });
  it('the reflected density is the visible one over 4 v·m (the Jacobian of the mirror)', () => {
    const v = spherical(1.1, 0.3);
    for (let k = 0; k < 100; k++) {
      const m = M.sampleVisibleNormalGGXAniso(...v, 0.2, 0.05, rand(), rand());
      const vm = v[0] * m[0] + v[1] * m[1] + v[2] * m[2];
      const want = M.visibleNormalPdfGGXAniso(...v, ...m, 0.2, 0.05) / (4 * vm);
      expect(M.reflectedPdfGGXAniso(...v, ...m, 0.2, 0.05)).toBeCloseTo(want, 10);
    }
  });
});
