// The DFG table as the GPU samples it (for tests): texture(uDfg, dfgTableUv(n·v, alpha)).rg with LinearFilter
// and ClampToEdge, from half-float texels (createDfgTexture), or from the float32 data with { half: false }.
import { DataUtils } from 'three';
import { dfgTableUv } from '../../src/math/integrate.js';

const toHalf = (x) => DataUtils.fromHalfFloat(DataUtils.toHalfFloat(x));

export function sampleDfgTable({ data, size }, nv, alpha, { half = true } = {}) {
  const [u, v] = dfgTableUv(nv, alpha);
  const texel = (c) => Math.min(Math.max(c * size - 0.5, 0), size - 1);
  const [x, y] = [texel(u), texel(v)];
  const [i, j] = [Math.min(Math.floor(x), size - 2), Math.min(Math.floor(y), size - 2)];
  const [fx, fy] = [x - i, y - j];
  const at = (ii, jj, k) => (half ? toHalf : Number)(data[(jj * size + ii) * 4 + k]);
  const row = (jj, k) => (1 - fx) * at(i, jj, k) + fx * at(i + 1, jj, k);
  return [0, 1].map((k) => (1 - fy) * row(j, k) + fy * row(j + 1, k));
}
