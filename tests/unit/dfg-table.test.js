// The shipped DFG tables against the float64 quadrature they are made from, texel by texel, and as the GPU samples
// them (half floats, bilinear between texel centres, clamped at the edges) against the adaptive dfgSplitSum.
import { describe, expect, it } from 'vitest';
import { DFG_TABLE_SIZE, dfgSplitSum, dfgTableUv } from '../../src/math/integrate.js';
import { dfgTableData, dfgTexel } from '../../src/lab/dfg-table.js';
import { DFG_TABLES } from '../../src/lab/dfg-tables.data.js';
import { LAB_TERMS } from '../../src/lab/lab-approximations.js';
import { sampleDfgTable } from '../support/dfg-lookup.js';

// probes between and on texel centres, denser toward grazing view and low roughness
const MUS = [1e-3, 0.002, 0.004, 0.007, 0.012, 0.02, 0.03, 0.04, 0.065, 0.1, 0.3, 0.75, 1];
const ALPHAS = [0.01, 0.012, 0.016, 0.025, 0.045, 0.07, 0.1, 0.22, 0.5, 1];

function worstError(terms, mus = MUS, alphas = ALPHAS) {
  const table = dfgTableData(terms);
  let worst = { error: 0 };
  for (const alpha of alphas) {
    for (const mu of mus) {
      const got = sampleDfgTable(table, mu, alpha);
      const ref = dfgSplitSum(mu, alpha, terms);
      const error = Math.max(Math.abs(got[0] - ref[0]), Math.abs(got[1] - ref[1]));
      if (error > worst.error) worst = { error, mu, alpha };
    }
  }
  return worst;
}

// every (D, V) pair the material lab offers
const LAB_PAIRS = Object.keys(LAB_TERMS.ndf).flatMap((ndf) =>
  Object.keys(LAB_TERMS.visibility).map((visibility) => ({ ndf, visibility })),
);

describe('shipped DFG tables (dfg-tables.data.js, npm run dfg-tables)', { timeout: 120_000 }, () => {
  it("hold exactly the lab's (D, V) pairs", () => {
    expect(Object.keys(DFG_TABLES).sort()).toEqual(LAB_PAIRS.map((t) => `${t.ndf}/${t.visibility}`).sort());
  });
  // every 7th texel (7 is prime to the 72 columns, so every column and row is visited) against the quadrature
  // three.js's toHalfFloat truncates: within one half-float step (2^-10 relative), 2^-24 absolute below 2^-14
  it.each(LAB_PAIRS)('equal the float64 split sum within half-float rounding (2^-10 relative) for %o', (terms) => {
    const { data, size } = dfgTableData(terms);
    let worst = 0;
    for (let t = 0; t < size * size; t += 7) {
      const ref = dfgTexel(terms, t % size, Math.floor(t / size));
      ref.forEach((x, k) => {
        const excess = Math.abs(data[4 * t + k] - x) / (2 ** -10 * Math.abs(x) + 2 ** -24);
        worst = Math.max(worst, excess);
      });
    }
    expect(worst).toBeLessThanOrEqual(1.001);
  });
});

describe('DFG table as the GPU samples it', { timeout: 60_000 }, () => {
  it.each(LAB_PAIRS)('is within 1e-3 of dfgSplitSum over n·v in [1e-3, 1], alpha in [0.01, 1] for %o', (terms) => {
    const worst = worstError(terms);
    expect(worst.error, JSON.stringify(worst)).toBeLessThan(1e-3);
  });
  it('holds down to alpha = 3e-4 as well, but not at the clamp alpha = 1e-4 (3.3e-3 near n·v = 0.007)', () => {
    expect(worstError({}, MUS.slice(0, 10), [3e-4, 1e-3, 3e-3, 6e-3]).error).toBeLessThan(1e-3);
    expect(worstError({}, MUS.slice(0, 10), [1e-4]).error).toBeGreaterThan(1e-3);
  });
  it('is decoded once per pair of terms, the default being GGX with height-correlated Smith', () => {
    expect(dfgTableData()).toBe(dfgTableData({ ndf: 'ggx', visibility: 'smithGGXCorrelated' }));
    expect(dfgTableData({ visibility: 'kelemen' })).not.toBe(dfgTableData());
    expect(dfgTableData().size).toBe(DFG_TABLE_SIZE);
  });
  it('puts n·v = 0 and 1, alpha = 0 and 1 on the first and last texel centres', () => {
    const n = DFG_TABLE_SIZE;
    dfgTableUv(0, 0).forEach((u) => expect(u).toBeCloseTo(0.5 / n, 14));
    dfgTableUv(1, 1).forEach((u) => expect(u).toBeCloseTo(1 - 0.5 / n, 14));
  });
});
