// The split sum's DFG tables, in plain JS (environment-maps.js makes the texture): [scale, bias] of the float64
// quadrature dfgSplitSum at the texels dfgTableUv maps (n·v, alpha) to, one table per pair of terms. Building one
// takes 0.4–5 s, which would freeze the page, so the app ships them precomputed as half floats
// (dfg-tables.data.js, written by `npm run dfg-tables` with computeDfgTable) and only decodes them.
import { DataUtils } from 'three';
import { DFG_DEFAULT_TERMS, DFG_TABLE_SIZE, dfgSplitSum, dfgTableUv } from '../math/integrate.js';
import { DFG_TABLES } from './dfg-tables.data.js';

const dfgTables = new Map();
// Gauss-Legendre nodes per piece of the split sum (the table as sampled stays within 1e-3, dfg-table.test.js):
// 12 keep it within 2e-4 of the adaptive quadrature; Cook-Torrance's kinks cut it into ~16 times as many pieces,
// where 8 do as well (1.9e-4) at half the cost
const dfgNodes = (visibility) => (visibility === 'cookTorrance' ? 8 : 12);
const keyOf = (terms) => {
  const t = { ...DFG_DEFAULT_TERMS, ...terms };
  return `${t.ndf}/${t.visibility}`;
};

/** [scale, bias] of texel (i across, j down) of the DFG table for terms { ndf, visibility }, in float64. */
export function dfgTexel(terms, i, j) {
  const t = { ...DFG_DEFAULT_TERMS, ...terms };
  const n = DFG_TABLE_SIZE;
  const alpha = (j / (n - 1)) ** 3;
  return dfgSplitSum(texelNv((i + 0.5) / n, alpha), alpha, t, { nodes: dfgNodes(t.visibility) });
}

/** The whole table in float64, row by row: [scale, bias] per texel (what scripts/dfg-tables.js ships). */
export function computeDfgTable(terms = {}) {
  const n = DFG_TABLE_SIZE;
  const out = new Float64Array(n * n * 2);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) out.set(dfgTexel(terms, i, j), (j * n + i) * 2);
  return out;
}

/**
 * The DFG table for terms { ndf, visibility } (see dfgSplitSum; default GGX + height-correlated Smith):
 * [scale, bias, 0, 1] per texel, laid out as dfgTableUv says; decoded from the shipped half floats once per page.
 */
export function dfgTableData(terms = {}) {
  const key = keyOf(terms);
  if (dfgTables.has(key)) return dfgTables.get(key);
  if (!(key in DFG_TABLES)) throw new Error(`No DFG table for ${key}: add the pair to scripts/dfg-tables.js`);
  const halves = decodeHalves(DFG_TABLES[key]);
  const n = DFG_TABLE_SIZE;
  if (halves.length !== n * n * 2) throw new Error(`DFG table ${key} is not ${n}²: run npm run dfg-tables`);
  const data = new Float32Array(n * n * 4);
  for (let t = 0; t < n * n; t++) {
    data.set([DataUtils.fromHalfFloat(halves[2 * t]), DataUtils.fromHalfFloat(halves[2 * t + 1]), 0, 1], 4 * t);
  }
  const table = { data, size: n };
  dfgTables.set(key, table);
  return table;
}

/** Little-endian uint16s as base64, and back (atob/btoa: in browsers and in Node). */
export function encodeHalves(halves) {
  let s = '';
  for (const h of halves) s += String.fromCharCode(h & 0xff, h >> 8);
  return btoa(s);
}

function decodeHalves(base64) {
  const s = atob(base64);
  const out = new Uint16Array(s.length / 2);
  for (let k = 0; k < out.length; k++) out[k] = s.charCodeAt(2 * k) | (s.charCodeAt(2 * k + 1) << 8);
  return out;
}

/** The n·v whose dfgTableUv across is u, for this alpha (the map rises with n·v): bisection to float64. */
function texelNv(u, alpha) {
  let [lo, hi] = [0, 1];
  for (let k = 0; k < 60; k++) {
    const mid = (lo + hi) / 2;
    if (dfgTableUv(mid, alpha)[0] < u) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}
