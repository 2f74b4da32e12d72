import { beforeAll, describe, expect, it } from 'vitest';
import {
  MERL_BYTES,
  MERL_DIMS,
  MERL_SAMPLES,
  measuredFromTable,
  merlIndex,
  merlNodeAngles,
  parseMerl,
  writeMerl,
} from '../../src/measured/merl.js';
import { modelBRDF } from '../../src/measured/fit.js';
import { directionsFromHalfDiff, halfDiffFromDirections } from '../../src/math/half-diff.js';

const GGX = { alpha: 0.2, f0: [0.04, 0.04, 0.04], cdiff: [0.3, 0.3, 0.3] };
const ABC = { a1: 40, a2: 2.5, f0: [0.9, 0.6, 0.3], cdiff: [0.05, 0.1, 0.2] };

/** A seeded generator (mulberry32), so the random nodes are the same on every run. */
function rng(seed) {
  let a = seed;
  return () => {
    a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Random nodes with l and v above the horizon (theta_d < 89° keeps them clear of it). */
function randomNodes(count, seed) {
  const r = rng(seed);
  const out = [];
  while (out.length < count) {
    const [i, j, k] = [Math.floor(r() * 90), Math.floor(r() * 89), Math.floor(r() * 180)];
    const a = merlNodeAngles(i, j, k);
    const d = directionsFromHalfDiff(a.thetaH, a.thetaD, a.phiD);
    if (d.l[2] > 0.02 && d.v[2] > 0.02) out.push({ i, j, k, ...d });
  }
  return out;
}

const relative = (a, b) => Math.abs(a - b) / Math.max(Math.abs(b), 1e-300);

describe('half/difference angles', () => {
  it('halfDiffFromDirections inverts directionsFromHalfDiff (the angles it was built from)', () => {
    const r = rng(1);
    for (let n = 0; n < 200; n++) {
      const [th, td, pd] = [r() * 1.5, r() * 1.5, (r() * 2 - 1) * 3.1];
      const { l, v } = directionsFromHalfDiff(th, td, pd);
      const back = halfDiffFromDirections(l, v);
      expect(back.thetaH).toBeCloseTo(th, 10);
      expect(back.thetaD).toBeCloseTo(td, 10);
      expect(back.phiD).toBeCloseTo(pd, 10);
    }
  });
});

describe('MERL lookups follow the reference reader (BRDFRead.cpp, Matusik et al. 2003)', () => {
  // The reference's own steps, written out apart from merl.js: its rotate_vector (Rodrigues), its
  // std_coords_to_half_diff_coords and its three index functions with their truncation.
  const rotate = (v, axis, angle) => {
    const [c, s] = [Math.cos(angle), Math.sin(angle)];
    const dot = axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2];
    const cross = [axis[1] * v[2] - axis[2] * v[1], axis[2] * v[0] - axis[0] * v[2], axis[0] * v[1] - axis[1] * v[0]];
    return v.map((x, i) => x * c + axis[i] * dot * (1 - c) + cross[i] * s);
  };
  const referenceIndex = (l, v) => {
    const h = [0, 1, 2].map((i) => (l[i] + v[i]) / 2);
    const len = Math.hypot(...h);
    const half = h.map((x) => x / len);
    const [thetaH, phiH] = [Math.acos(half[2]), Math.atan2(half[1], half[0])];
    const diff = rotate(rotate(l, [0, 0, 1], -phiH), [0, 1, 0], -thetaH);
    const [thetaD, phiD0] = [Math.acos(diff[2]), Math.atan2(diff[1], diff[0])];
    const ih = thetaH <= 0 ? 0 : Math.min(Math.trunc(Math.sqrt((thetaH / (Math.PI / 2)) * 90 * 90)), 89);
    const id = Math.min(Math.max(Math.trunc((thetaD / (Math.PI / 2)) * 90), 0), 89);
    const phiD = phiD0 < 0 ? phiD0 + Math.PI : phiD0;
    const ip = Math.min(Math.max(Math.trunc((phiD / Math.PI) * 180), 0), 179);
    return ip + id * 180 + ih * 180 * 90;
  };

  it('lookupNearest reads the node the reference indexes, for random direction pairs', () => {
    const table = new Float64Array(3 * MERL_SAMPLES);
    for (let n = 0; n < MERL_SAMPLES; n++) table[n] = table[n + MERL_SAMPLES] = table[n + 2 * MERL_SAMPLES] = n;
    const m = measuredFromTable(table);
    const r = rng(7);
    for (let n = 0; n < 2000; n++) {
      const dir = () => {
        const [t, p] = [Math.acos(r()), r() * 2 * Math.PI];
        return [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
      };
      const [l, v] = [dir(), dir()];
      expect(m.lookupNearest(l, v)[0]).toBe(referenceIndex(l, v));
    }
  });

  it('the layout: index (θh, θd, φd) with φd fastest, the nodes at the start of each reference bin', () => {
    expect(merlIndex(1, 2, 3)).toBe(3 + 2 * 180 + 1 * 180 * 90);
    const a = merlNodeAngles(45, 30, 90);
    expect(a.thetaH).toBeCloseTo((45 / 90) ** 2 * (Math.PI / 2), 15); // √(θh/90°)·90 = 45
    expect([a.thetaD, a.phiD].map((x) => (x * 180) / Math.PI)).toEqual([30, 90].map((x) => expect.closeTo(x, 12)));
  });
});

describe('writeMerl → parseMerl round trip (truth: the analytic model at each node)', () => {
  let ggx;
  let abc;
  beforeAll(() => {
    ggx = parseMerl(writeMerl(modelBRDF('ggx', GGX)));
    abc = parseMerl(writeMerl(modelBRDF('abc', ABC)));
  });

  it('the file is 90 × 90 × 180, 34,992,012 bytes; below-horizon nodes are written as missing', () => {
    const buffer = writeMerl(() => [1, 1, 1]);
    expect(buffer.byteLength).toBe(MERL_BYTES);
    expect(Array.from(new Int32Array(buffer, 0, 3))).toEqual([...MERL_DIMS]);
    const m = parseMerl(buffer);
    const a = merlNodeAngles(89, 89, 0); // θh ≈ 88°, θd 89°, φd 0: l at θh + θd, far below the horizon
    expect(directionsFromHalfDiff(a.thetaH, a.thetaD, a.phiD).l[2]).toBeLessThan(0);
    expect(m.table[merlIndex(89, 89, 0)]).toBe(-1);
    expect(m.table[merlIndex(0, 0, 0)]).toBeCloseTo(1, 14); // (1 / scale) · scale
  });

  for (const [name, params, get] of [
    ['GGX α 0.2, f0 0.04, c_diff 0.3', GGX, () => ggx],
    ['ABC a1 40, a2 2.5, coloured', ABC, () => abc],
  ]) {
    it(`${name}: lookup at the nodes equals the model to float64 precision`, () => {
      const f = modelBRDF(name.startsWith('GGX') ? 'ggx' : 'abc', params);
      let worst = 0;
      for (const node of randomNodes(1000, 3)) {
        const [got, want] = [get().lookup(node.l, node.v), f(node.l, node.v)];
        for (let c = 0; c < 3; c++) worst = Math.max(worst, relative(got[c], want[c]));
      }
      expect(worst).toBeLessThan(1e-13);
    });
  }

  it(
    'between nodes: the interpolated lookup is within 5 % of GGX at the ' + 'median, and closer than the nearest node',
    () => {
      const f = modelBRDF('ggx', GGX);
      const r = rng(11);
      const errors = { lookup: [], lookupNearest: [] };
      for (let n = 0; n < 2000; n++) {
        const [th, td, pd] = [
          ((r() * 88) / 180) * Math.PI * (r() < 0.5 ? 0.1 : 1),
          ((r() * 80) / 180) * Math.PI,
          r() * Math.PI,
        ];
        const { l, v } = directionsFromHalfDiff(th, td, pd);
        if (!(l[2] > 0.05 && v[2] > 0.05)) continue;
        for (const key of Object.keys(errors)) errors[key].push(relative(ggx[key](l, v)[1], f(l, v)[1]));
      }
      const median = (x) => x.sort((a, b) => a - b)[Math.floor(x.length / 2)];
      expect(median(errors.lookup)).toBeLessThan(0.05);
      expect(median(errors.lookup)).toBeLessThan(median(errors.lookupNearest));
    },
  );

  it('below the horizon every lookup is 0', () => {
    expect(ggx.lookup([0, 0.6, -0.8], [0, 0, 1])).toEqual([0, 0, 0]);
    expect(ggx.lookupNearest([0.6, 0, 0.8], [0, 0, -1])).toEqual([0, 0, 0]);
  });
});

describe('malformed files are refused with a message that says which fault', () => {
  const header = (dims, bytes = 12) => {
    const b = new ArrayBuffer(bytes);
    new Int32Array(b, 0, 3).set(dims);
    return b;
  };
  const cases = [
    ['empty', () => new ArrayBuffer(0), /Empty file/],
    ['shorter than the header', () => new ArrayBuffer(7), /Truncated header: 7 bytes/],
    ['truncated data', () => header(MERL_DIMS, 1_000_000), /Truncated file: 1,000,000 bytes of 34,992,012/],
    ['wrong dimensions', () => header([90, 90, 360], MERL_BYTES), /Wrong dimensions 90 × 90 × 360/],
    ['negative dimensions', () => header([-90, 90, 180], MERL_BYTES), /Wrong dimensions -90 × 90 × 180/],
    ['a header that claims 2 GB', () => header([90, 90, 180 * 61], 4096), /claims 90 × 90 × 10980 samples, 2\.1 GB/],
    ['trailing bytes', () => header(MERL_DIMS, MERL_BYTES + 8), /Wrong size: 34,992,020 bytes, 8 more/],
  ];
  for (const [name, make, message] of cases) it(name, () => expect(() => parseMerl(make())).toThrow(message));

  it('a NaN sample, located', () => {
    const b = header(MERL_DIMS, MERL_BYTES);
    new DataView(b).setFloat64(12 + 8 * (MERL_SAMPLES + merlIndex(2, 3, 4)), NaN, true);
    expect(() => parseMerl(b)).toThrow(/NaN in the G block at node \(θh, θd, φd\) = \(2, 3, 4\)/);
  });
  it('an infinite sample', () => {
    const b = header(MERL_DIMS, MERL_BYTES);
    new DataView(b).setFloat64(12 + 8 * 5, Infinity, true);
    expect(() => parseMerl(b)).toThrow(/Infinity in the R block/);
  });
});
