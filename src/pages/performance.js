// performance.html: cost against accuracy for every family of terms, from bench/results/latest.json
// (written by `npm run bench`): a Pareto chart per family and the full table.
import '../styles.css';
import report from '../../bench/results/latest.json';
import { createPlot } from '../core/plot.js';
import { SERIES_COLORS } from '../core/palettes.js';

const ERROR_FLOOR = 1e-7; // the reference has error 0, which a log axis cannot show: drawn on the floor
const root = document.getElementById('families');
const costSelect = document.getElementById('cost');
document.getElementById('machine').textContent =
  `Measured ${report.date.slice(0, 10)} on ${report.machine.cpu} (${report.machine.cores} cores), Node ${report.machine.node}, ` +
  `${report.machine.chromium}, GPU: ${report.machine.gpuRenderer}. GPU pass: ${report.gpuSetup.size}² pixels × ${report.gpuSetup.loops} ` +
  `evaluations per pixel, median of ${report.gpuSetup.frames} drained frames; the empty pass takes ${report.gpuSetup.baselineMsPerFrame?.toFixed(2) ?? '?'} ms of each.`;

const costOf = (v) => (costSelect.value === 'gpu' ? v.gpuRelative : v.cpuNsPerEval);
const costLabel = () => (costSelect.value === 'gpu' ? 'GPU cost, relative to the cheapest variant' : 'CPU cost (ns per evaluation, JS)');

const plots = [];
function render() {
  plots.splice(0).forEach((p) => p.dispose());
  root.replaceChildren();
  for (const f of report.families) {
    const section = document.createElement('section');
    section.innerHTML = `<h2>${f.title}</h2><p class="domain">Error of ${f.errorOf} against the float64 reference over ${f.domain}.</p>`;
    root.append(section);
    const costs = [...new Set(f.variants.map(costOf))].sort((a, b) => a - b);
    const lo = costs[0];
    const hi = costs[costs.length - 1];
    plots.push(createPlot(section, {
      title: `${f.title}: largest error against cost (lower left is better; the exact reference sits at 1e-7)`,
      xLabel: costLabel(),
      yLabel: 'max |error|',
      x: { min: lo * 0.9, max: hi * 1.1 },
      y: { min: ERROR_FLOOR / 2, max: 2, log: true },
      series: f.variants.map((v, i) => ({ label: v.label, stroke: SERIES_COLORS[i % SERIES_COLORS.length], width: 0, points: true })),
      data: [costs, ...f.variants.map((v) => costs.map((c) => (c === costOf(v) ? Math.max(v.error.maxAbs, ERROR_FLOOR) : null)))],
      filename: `cost-accuracy-${f.key}`,
      height: 240,
    }));
    const table = document.createElement('table');
    table.className = 'data-table compact';
    table.innerHTML = '<thead><tr><th>Variant</th><th>max |error|</th><th>RMS error</th><th>CPU ns/eval</th><th>GPU ms/frame</th><th>GPU relative</th></tr></thead><tbody>' +
      f.variants.map((v, i) => `<tr><td><span class="swatch" style="background:${SERIES_COLORS[i % SERIES_COLORS.length]}"></span> ${v.label}</td>` +
        `<td>${v.error.maxAbs === 0 ? '0 (reference)' : v.error.maxAbs.toExponential(2)}</td><td>${v.error.rms.toExponential(2)}</td>` +
        `<td>${v.cpuNsPerEval.toFixed(1)}</td><td>${v.gpuMsPerFrame.toFixed(2)}</td><td>${v.gpuRelative.toFixed(2)}×</td></tr>`).join('') + '</tbody>';
    section.append(table);
  }
}
costSelect.addEventListener('change', render);
render();

// three.js for scale, and what each page costs to open
const vt = report.versusThree;
const extra = document.getElementById('pages');
extra.innerHTML =
  `<h2>Against three.js</h2><p>A sphere at ${vt.size}² pixels with the terms of MeshStandardMaterial (GGX, height-correlated Smith, ` +
  `Schlick with F0 = 0.04, Lambert, one punctual light): this app's shader takes <strong>${vt.oursMsPerFrame.toFixed(2)} ms</strong> a frame, ` +
  `MeshStandardMaterial <strong>${vt.threeMsPerFrame.toFixed(2)} ms</strong>: a ratio of <strong>${vt.ratio.toFixed(2)}</strong>.</p>` +
  '<h2>What each page loads</h2><table class="data-table compact"><thead><tr><th>Page</th><th>JavaScript (KiB, uncompressed)</th><th>files</th><th>load (ms)</th><th>first 3-D frame (ms)</th></tr></thead><tbody>' +
  report.pages.map((p) => `<tr><td>${p.page}</td><td>${p.jsKB.toFixed(0)}</td><td>${p.jsFiles}</td><td>${p.loadMs.toFixed(0)}</td><td>${p.firstFrameMs === null ? '—' : p.firstFrameMs.toFixed(0)}</td></tr>`).join('') +
  '</tbody></table>';
(globalThis.__shadingLab ??= {}).performance = report;
