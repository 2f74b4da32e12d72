// The split sum's DFG table, in plain JS (environment-maps.js makes the texture): [scale, bias] of the float64
// quadrature dfgSplitSum at the texels dfgTableUv maps (n·v, alpha) to, one table per pair of terms, cached.
import { DFG_DEFAULT_TERMS, DFG_TABLE_SIZE, DFG_TABLE_WARP, dfgSplitSum } from '../../math/integrate.js';

const dfgTables = new Map();
const DFG_NODES = 12; // Gauss-Legendre nodes per piece: within 2e-4 of the adaptive split sum (tests/unit/dfg-table.test.js)
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
    const alpha = (j / (n - 1)) ** DFG_TABLE_WARP[1];
    for (let i = 0; i < n; i++) {
      const [scale, bias] = dfgSplitSum((i / (n - 1)) ** DFG_TABLE_WARP[0], alpha, t, { nodes: DFG_NODES });
      data.set([scale, bias, 0, 1], (j * n + i) * 4);
    }
  }
  const table = { data, size: n };
  dfgTables.set(key, table);
  return table;
}
