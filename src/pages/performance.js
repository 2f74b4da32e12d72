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
    const against = f.referenceLabel ?? 'the float64 reference';
    section.innerHTML = `<h2>${f.title}</h2><p class="domain">Error of ${f.errorOf} against ${against} over ${f.domain}.` +
      `${f.referenceNote ? ` The reference's own uncertainty: ${f.referenceNote}.` : ''}</p>`;
    root.append(section);
    const costs = [...new Set(f.variants.map(costOf))].sort((a, b) => a - b);
    const lo = costs[0];
    const hi = costs[costs.length - 1];
    plots.push(createPlot(section, {
      title: `${f.title}: largest error against cost (lower left is better${f.variants.some((v) => v.error.maxAbs === 0) ? '; the exact reference sits at 1e-7' : ''})`,
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

// image-based lighting: each method's error against the lab's Monte Carlo reference, against its GPU time
function renderIbl(ibl) {
  const section = document.createElement('section');
  section.innerHTML = '<h2>Image-based lighting against the reference</h2>' +
    `<p class="domain">The material lab's environment methods on a ${ibl.setup.resolution}² sphere, each against the lab's converged ` +
    `Monte Carlo reference (${ibl.setup.referenceSamples} samples per pixel): relative RMS error over the sphere against the GPU time ` +
    `of the method's pass (median of ${ibl.setup.timingRuns}). Importance sampling is one curve, N = 4 to 256 samples.</p>`;
  extra.before(section);
  const cases = [...new Set(ibl.rows.map((r) => `${r.environment}|${r.material}|${r.alpha}`))];
  for (const c of cases) {
    const rows = ibl.rows.filter((r) => `${r.environment}|${r.material}|${r.alpha}` === c);
    const [environment, material, alpha] = c.split('|');
    const methods = [...new Set(rows.map((r) => r.method))];
    const xs = [...new Set(rows.map((r) => r.ms))].sort((a, b) => a - b);
    plots.push(createPlot(section, {
      title: `${environment}, ${material} α ${alpha}: relative RMS error against GPU time (lower left is better)`,
      xLabel: 'GPU time of the pass (ms)',
      yLabel: 'relative RMS error',
      x: { min: xs[0] * 0.8, max: xs[xs.length - 1] * 1.2, log: true },
      y: { min: 0.005, max: 10 ** Math.ceil(Math.log10(Math.max(...rows.map((r) => r.relative)) * 1.5)), log: true },
      series: methods.map((m, i) => ({ label: m, stroke: SERIES_COLORS[i % SERIES_COLORS.length], width: m === 'importance' ? 1.5 : 0, points: true, spanGaps: true })),
      data: [xs, ...methods.map((m) => xs.map((x) => rows.find((r) => r.method === m && r.ms === x)?.relative ?? null))],
      filename: `ibl-${environment}-${material}`,
      height: 220,
    }));
  }
  const table = document.createElement('table');
  table.className = 'data-table compact';
  table.innerHTML = '<thead><tr><th>Environment, material</th><th>Method</th><th>GPU ms</th><th>RMS error</th><th>relative</th></tr></thead><tbody>' +
    ibl.rows.map((r) => `<tr><td>${r.environment}, ${r.material} α ${r.alpha}</td><td>${r.samples ? `importance, N = ${r.samples}` : r.method}</td>` +
      `<td>${r.ms.toFixed(2)}</td><td>${r.rms.toExponential(2)}</td><td>${(r.relative * 100).toFixed(2)} %</td></tr>`).join('') + '</tbody>';
  section.append(table);
}

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
if (report.ibl) renderIbl(report.ibl);
(globalThis.__shadingLab ??= {}).performance = report;
