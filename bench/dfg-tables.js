// node bench/dfg-tables.js: how long the split sum's float64 quadrature takes: each DFG table (DFG_TABLE_SIZE²
// texels; npm run dfg-tables builds them ahead, the page only decodes them, also timed), the energy widget's
// sweep, and one adaptive evaluation. Wall-clock on this machine; the figures vary with its load.
import { computeDfgTable, dfgTableData } from '../src/lab/dfg-table.js';
import { DFG_TABLE_SIZE, albedoGGX, averageAlbedo } from '../src/math/integrate.js';
import { termsWith } from '../src/lab/lab-approximations.js';

const time = (fn) => {
  const t0 = performance.now();
  fn();
  return performance.now() - t0;
};

console.log(`DFG table (${DFG_TABLE_SIZE} x ${DFG_TABLE_SIZE}), ms to build (npm run dfg-tables) / to decode (page):`);
for (const ndf of termsWith('ndf', 'dfgTable')) {
  for (const visibility of termsWith('visibility', 'dfgTable')) {
    const build = time(() => computeDfgTable({ ndf, visibility }));
    const decode = time(() => dfgTableData({ ndf, visibility }));
    console.log(`  ${`${ndf} / ${visibility}`.padEnd(32)}${build.toFixed(0)} / ${decode.toFixed(1)}`);
  }
}
const sweep = time(() => {
  for (const alpha of [0.05, 0.25, 0.5, 0.75, 1]) {
    for (let deg = 0.5; deg < 90; deg++) albedoGGX(Math.cos((deg * Math.PI) / 180), alpha, {}, { nodes: 24 });
    averageAlbedo((mu) => albedoGGX(mu, alpha));
    albedoGGX(1, alpha);
  }
});
console.log(`energy widget, default sweep (5 roughnesses): ${sweep.toFixed(0)} ms`);
const grazing = time(() => albedoGGX(1e-3, 0.01));
console.log(`one adaptive albedoGGX at mu 1e-3, alpha 0.01 (the hardest): ${grazing.toFixed(1)} ms`);
