// The split sum's DFG table, in plain JS (environment-maps.js makes the texture): [scale, bias] of the float64
// quadrature dfgSplitSum at the texels dfgTableUv maps (n·v, alpha) to, one table per pair of terms, cached.
import { DFG_DEFAULT_TERMS, DFG_TABLE_SIZE, dfgSplitSum, dfgTableUv } from '../../math/integrate.js';

const dfgTables = new Map();
// Gauss-Legendre nodes per piece of the split sum (the table as sampled stays within 1e-3, dfg-table.test.js):
// 12 keep it within 2e-4 of the adaptive quadrature; Cook-Torrance's kinks cut it into ~16 times as many pieces,
// where 8 do as well (1.9e-4) at half the cost
const dfgNodes = (visibility) => (visibility === 'cookTorrance' ? 8 : 12);
/**
 * The DFG table for terms { ndf, visibility } (see dfgSplitSum; default GGX + height-correlated Smith):
 * [scale, bias, 0, 1] per texel, laid out as dfgTableUv says; computed once per page and per pair of terms.
 */
export function dfgTableData(terms = {}) {
  const t = { ...DFG_DEFAULT_TERMS, ...terms };
  const key = `${t.ndf}/${t.visibility}`;
  if (dfgTables.has(key)) return dfgTables.get(key);
  const n = DFG_TABLE_SIZE;
  const data = new Float32Array(n * n * 4);
  for (let j = 0; j < n; j++) {
    const alpha = (j / (n - 1)) ** 3;
    for (let i = 0; i < n; i++) {
      const [scale, bias] = dfgSplitSum(texelNv((i + 0.5) / n, alpha), alpha, t, { nodes: dfgNodes(t.visibility) });
      data.set([scale, bias, 0, 1], (j * n + i) * 4);
    }
  }
  const table = { data, size: n };
  dfgTables.set(key, table);
  return table;
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
