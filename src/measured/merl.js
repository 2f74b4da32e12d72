// Measured isotropic BRDFs in the MERL format (Matusik, Pfister, Brand, McMillan 2003, "A data-driven
// reflectance model"), read and written without the DOM, so that Node and a Web Worker can use it.
//
// The file: three int32 dimensions (90, 90, 180), then the red, green and blue blocks of 90·90·180 float64,
// little-endian, each block indexed [theta_h][theta_d][phi_d] with phi_d fastest. A stored value times the
// channel's scale (1/1500, 1.15/1500, 1.66/1500) is the BRDF in 1/sr; a negative value is a missing sample.
// Node (i, j, k) sits where the reference reader's index of a direction pair first becomes (i, j, k)
// (BRDFRead.cpp truncates): theta_h = (i/90)² · 90°, theta_d = j°, phi_d = k°. phi_d covers [0°, 180°)
// only: reciprocity makes f(phi_d + 180°) = f(phi_d).
import { directionsFromHalfDiff, halfDiffFromDirections } from '../math/half-diff.js';
import { MERL_DIMS, MERL_SAMPLES, merlCoordinates, merlIndex, merlNodeAngles } from '../math/merl-coordinates.js';

export { MERL_DIMS, MERL_SAMPLES, merlCoordinates, merlIndex, merlNodeAngles };

export const MERL_SCALE = Object.freeze([1 / 1500, 1.15 / 1500, 1.66 / 1500]);
const HEADER_BYTES = 12;
export const MERL_BYTES = HEADER_BYTES + 3 * 8 * MERL_SAMPLES; // 34,992,012
const [NH, ND, NP] = MERL_DIMS;
const BIG_CLAIM = 2 ** 30; // a header claiming more than this many bytes is refused before anything else

const GB = (bytes) => `${(bytes / 1e9).toFixed(1)} GB`;

/** Throws an Error naming what is wrong with the header or the size; returns nothing when both are right. */
function checkLayout(buffer) {
  const n = buffer.byteLength;
  if (n === 0) throw new Error('Empty file: a MERL BRDF file is 34,992,012 bytes.');
  if (n < HEADER_BYTES)
    throw new Error(`Truncated header: ${n} bytes, but a MERL file starts with three int32 dimensions (12 bytes).`);
  const view = new DataView(buffer);
  const dims = [0, 4, 8].map((o) => view.getInt32(o, true));
  const claimed = HEADER_BYTES + 24 * dims.reduce((a, d) => a * Math.abs(d), 1);
  if (claimed > BIG_CLAIM) {
    throw new Error(
      `The header claims ${dims.join(' × ')} samples, ${GB(claimed)} of data; ` +
        'a MERL file holds 90 × 90 × 180 (35 MB). Refused.',
    );
  }
  if (dims.some((d, i) => d !== MERL_DIMS[i])) {
    throw new Error(`Wrong dimensions ${dims.join(' × ')}: a MERL file has 90 × 90 × 180 (θh × θd × φd).`);
  }
  if (n < MERL_BYTES)
    throw new Error(`Truncated file: ${n.toLocaleString('en')} bytes of ${MERL_BYTES.toLocaleString('en')}.`);
  if (n > MERL_BYTES)
    throw new Error(
      `Wrong size: ${n.toLocaleString('en')} bytes, ${(n - MERL_BYTES).toLocaleString('en')} more than ` +
        `a MERL file’s ${MERL_BYTES.toLocaleString('en')}.`,
    );
}

const littleEndianHost = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

/** The float64 samples after the header (copied: they start at byte 12, not on an 8-byte boundary). */
function readSamples(buffer) {
  if (littleEndianHost) return new Float64Array(buffer.slice(HEADER_BYTES));
  const view = new DataView(buffer);
  return Float64Array.from({ length: 3 * MERL_SAMPLES }, (_, i) => view.getFloat64(HEADER_BYTES + 8 * i, true));
}

/**
 * Parses a MERL file. Throws an Error that says what is wrong: empty, truncated, wrong dimensions, a header
 * claiming gigabytes, wrong size, a NaN or infinite sample. Returns measuredFromTable() of its samples in 1/sr.
 */
export function parseMerl(buffer) {
  checkLayout(buffer);
  const table = readSamples(buffer);
  for (let c = 0; c < 3; c++) {
    for (let n = c * MERL_SAMPLES; n < (c + 1) * MERL_SAMPLES; n++) {
      const x = table[n];
      if (!Number.isFinite(x)) {
        const r = n % MERL_SAMPLES;
        const at = [Math.floor(r / (ND * NP)), Math.floor(r / NP) % ND, r % NP];
        throw new Error(
          `${x} in the ${'RGB'[c]} block at node (θh, θd, φd) = (${at.join(', ')}): the file is damaged.`,
        );
      }
      table[n] = x < 0 ? -1 : x * MERL_SCALE[c];
    }
  }
  return measuredFromTable(table);
}

/** A coordinate within rounding of a node is that node: a steep lobe would magnify its 1e-14 into 1e-9. */
const snap = (x) => (Math.abs(x - Math.round(x)) < 1e-9 ? Math.round(x) : x);

/** Trilinear weights of a coordinate on an axis of n nodes, clamped at both ends (theta axes). */
function clampedAxis(u, n) {
  const x = Math.min(Math.max(u, 0), n - 1);
  const i = Math.min(Math.floor(x), n - 2);
  return [i, i + 1, x - i];
}

/**
 * A measured BRDF over its table (Float64Array, 3 · 90 · 90 · 180, channel-major, values in 1/sr, -1 where
 * missing). Lookups return [r, g, b] in 1/sr, 0 when l or v is at or below the horizon:
 *  - lookup(l, v): trilinear between nodes in the file's own coordinates (sqrt-spaced theta_h, linear theta_d,
 *    phi_d periodic over 180°), missing nodes left out of the weights; exact at the nodes.
 *  - lookupNearest(l, v): the reference reader's rule, the node at the truncated indices.
 * valueAt(thetaH, thetaD, phiD) is lookup's interpolation in half/difference angles.
 */
export function measuredFromTable(table) {
  let missing = 0;
  for (let n = 0; n < table.length; n++) if (table[n] < 0) missing++;

  const valueAt = (thetaH, thetaD, phiD) => {
    const [u, t, p] = merlCoordinates(thetaH, thetaD, phiD).map(snap);
    const [i0, i1, fi] = clampedAxis(u, NH);
    const [j0, j1, fj] = clampedAxis(t, ND);
    const k0 = Math.min(Math.floor(p), NP - 1);
    const fk = p - k0;
    const k1 = (k0 + 1) % NP;
    // the eight nodes around the point and their weights, once for the three channels (a lookup per vertex of
    // the 3-D lobe at every change: no arrays made in the channel loop)
    const nodes = [];
    const weights = [];
    for (const [i, wi] of [
      [i0, 1 - fi],
      [i1, fi],
    ])
      for (const [j, wj] of [
        [j0, 1 - fj],
        [j1, fj],
      ])
        for (const [k, wk] of [
          [k0, 1 - fk],
          [k1, fk],
        ]) {
          nodes.push(merlIndex(i, j, k));
          weights.push(wi * wj * wk);
        }
    const out = [0, 0, 0];
    for (let c = 0; c < 3; c++) {
      let sum = 0;
      let weight = 0;
      for (let n = 0; n < 8; n++) {
        const x = table[c * MERL_SAMPLES + nodes[n]];
        if (weights[n] > 0 && x >= 0) {
          sum += weights[n] * x;
          weight += weights[n];
        }
      }
      out[c] = weight > 0 ? sum / weight : 0;
    }
    return out;
  };

  const above = (l, v) => l[2] > 0 && v[2] > 0;
  return {
    dims: MERL_DIMS,
    table,
    missing,
    valueAt,
    lookup(l, v) {
      if (!above(l, v)) return [0, 0, 0];
      const a = halfDiffFromDirections(l, v);
      return valueAt(a.thetaH, a.thetaD, a.phiD);
    },
    lookupNearest(l, v) {
      if (!above(l, v)) return [0, 0, 0];
      const a = halfDiffFromDirections(l, v);
      const [u, t, p] = merlCoordinates(a.thetaH, a.thetaD, a.phiD);
      const idx = merlIndex(
        Math.min(Math.floor(u), NH - 1),
        Math.min(Math.floor(t), ND - 1),
        Math.min(Math.floor(p), NP - 1),
      );
      return [0, 1, 2].map((c) => Math.max(table[c * MERL_SAMPLES + idx], 0));
    },
  };
}

/**
 * Tabulates f(l, v) → [r, g, b] (1/sr) at every node into a MERL file (an ArrayBuffer). Nodes where l or v
 * is at or below the horizon cannot be measured and are written as missing (-1), as in the database.
 */
export function writeMerl(f) {
  const buffer = new ArrayBuffer(MERL_BYTES);
  const view = new DataView(buffer);
  MERL_DIMS.forEach((d, i) => view.setInt32(4 * i, d, true));
  const data = new Float64Array(3 * MERL_SAMPLES);
  for (let i = 0; i < NH; i++) {
    for (let j = 0; j < ND; j++) {
      for (let k = 0; k < NP; k++) {
        const a = merlNodeAngles(i, j, k);
        const { l, v } = directionsFromHalfDiff(a.thetaH, a.thetaD, a.phiD);
        const rgb = l[2] > 0 && v[2] > 0 ? f(l, v) : null;
        const n = merlIndex(i, j, k);
        for (let c = 0; c < 3; c++) data[c * MERL_SAMPLES + n] = rgb ? rgb[c] / MERL_SCALE[c] : -1;
      }
    }
  }
  if (littleEndianHost) new Uint8Array(buffer, HEADER_BYTES).set(new Uint8Array(data.buffer));
  else data.forEach((x, n) => view.setFloat64(HEADER_BYTES + 8 * n, x, true));
  return buffer;
}
