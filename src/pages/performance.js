// performance.html: cost against accuracy for every family of terms, from the bench's report (written by `npm run
// bench` to bench/results/latest.json and published here by bench/publish-report.js): a Pareto chart per family and
// the full table.
import '../styles.css';
import report from './data/bench-report.json';
import { renderIbl, row } from './performance-ibl.js';
import { materialxSection } from './openpbr-materialx.js';
import { createPlot } from '../core/ui/plot.js';
import { SERIES_COLORS } from '../core/ui/palettes.js';
import { publish } from '../core/framework/debug-hooks.js';

const ERROR_FLOOR = 1e-7; // the reference has error 0, which a log axis cannot show: drawn on the floor
const root = document.getElementById('families');
const costSelect = document.getElementById('cost');
document.getElementById('machine').textContent =
  `Measured ${report.date.slice(0, 10)} on ${report.machine.cpu} (${report.machine.cores} cores), ` +
  `Node ${report.machine.node}, ${report.machine.chromium}, GPU: ${report.machine.gpuRenderer}. ` +
  `GPU pass: ${report.gpuSetup.size}² pixels × ${report.gpuSetup.loops} evaluations per pixel, median of ` +
  `${report.gpuSetup.frames} drained frames; the empty pass takes ` +
  `${report.gpuSetup.baselineMsPerFrame?.toFixed(2) ?? '?'} ms of each.` +
  (report.familiesMeasured
    ? ` The term families' ${report.familiesMeasured.timedCpu ? 'errors and CPU costs' : 'errors'} were ` +
      'measured again on ' +
      `${report.familiesMeasured.date.slice(0, 10)} (npm run bench -- --only families); their ` +
      `${report.familiesMeasured.timedCpu ? 'GPU columns are' : 'costs are'} from the full run.`
    : '');

const costOf = (v) => (costSelect.value === 'gpu' ? v.gpuRelative : v.cpuNsPerEval);
/** What a family's GPU costs are relative to: the cheapest variant, or the one it names (relativeTo; its label's
 * last part, after a colon: OpenPBR's "+ specular: the talk's model"). */
const relativeWords = (f) =>
  f.relativeTo
    ? f.variants
        .find((v) => v.key === f.relativeTo)
        .label.split(': ')
        .pop()
    : 'the cheapest variant';
const costLabel = (f) =>
  costSelect.value === 'gpu' ? `GPU cost, relative to ${relativeWords(f)}` : 'CPU cost (ns per evaluation, JS)';

const plots = [];
const measureOf = (v) => v.error ?? v.difference;
const maxText = (v) => (v.kind === 'reference' ? '0 (reference)' : measureOf(v).maxAbs.toExponential(2));
const againstText = (v) =>
  v.kind === 'reference'
    ? 'reference'
    : `${v.kind === 'difference' ? 'differs from' : 'error against'} ${v.againstLabel}`;
const colourOf = (f, v) => SERIES_COLORS[f.variants.indexOf(v) % SERIES_COLORS.length];

/**
 * Error against cost, for the reference and what approximates a model: different models are not on it, nor is
 * a variant without the cost chosen (a Monte Carlo walk run once, offline; a quadrature looked up has no CPU cost).
 */
function errorChart(section, f, all) {
  const variants = all.filter((v) => costOf(v) !== null);
  if (!variants.length) {
    section.append(Object.assign(document.createElement('p'), { textContent: `No ${costLabel(f)} for this family.` }));
    return;
  }
  const costs = [...new Set(variants.map(costOf))].sort((a, b) => a - b);
  plots.push(
    createPlot(section, {
      title:
        `${f.title.split(':')[0]}: largest error of each approximation against its cost ` +
        '(lower left is better; exact forms sit at 1e-7)',
      xLabel: costLabel(f),
      yLabel: 'max |error|',
      x: { min: costs[0] * 0.9, max: costs[costs.length - 1] * 1.1 },
      y: { min: ERROR_FLOOR / 2, max: 2, log: true },
      series: variants.map((v) => ({
        label: v.kind === 'reference' ? `${v.label} (reference)` : `${v.label} (vs ${v.againstLabel})`,
        stroke: colourOf(f, v),
        width: 0,
        points: true,
      })),
      data: [
        costs,
        ...variants.map((v) => costs.map((c) => (c === costOf(v) ? Math.max(v.error.maxAbs, ERROR_FLOOR) : null))),
      ],
      filename: `cost-accuracy-${f.key}`,
      height: 240,
    }),
  );
}

// no cost: a reference run once, offline, or (OpenPBR's stacks) a quadrature computed once and looked up
const cost = (x, digits, v) => (x !== null ? x.toFixed(digits) : v.kind === 'reference' ? '— (run offline)' : '—');

function rowsOf(f, variants) {
  return variants
    .map((v) =>
      row([
        `<span class="swatch" style="background:${colourOf(f, v)}"></span> ${v.label}`,
        againstText(v),
        maxText(v),
        measureOf(v).rms.toExponential(2),
        cost(v.cpuNsPerEval, 1, v),
        cost(v.gpuMsPerFrame, 2, v),
        `${cost(v.gpuRelative, 2, v)}${v.gpuRelative === null ? '' : '×'}`,
      ]),
    )
    .join('');
}

function render() {
  plots.splice(0).forEach((p) => p.dispose());
  root.replaceChildren();
  for (const f of report.families) {
    const approximations = f.variants.filter((v) => v.kind !== 'difference');
    const others = f.variants.filter((v) => v.kind === 'difference');
    const section = document.createElement('section');
    section.innerHTML =
      `<h2>${f.title}</h2><p class="domain">${f.errorOf} over ${f.domain}.` +
      `${f.referenceNote ? ` The reference is itself measured: ${f.referenceNote}.` : ''}</p>`;
    root.append(section);
    if (approximations.length > 1) errorChart(section, f, approximations);
    const relative = f.relativeTo ? `GPU relative to ${relativeWords(f)}` : 'GPU relative';
    const head = (what) =>
      `<tr><th>Variant</th><th>Measured against</th><th>max |${what}|</th><th>RMS ${what}</th>` +
      `<th>CPU ns/eval</th><th>GPU ms/frame</th><th>${relative}</th></tr>`;
    const table = document.createElement('table');
    table.className = 'data-table compact';
    table.innerHTML =
      `<thead>${head('error')}</thead><tbody>${rowsOf(f, approximations)}</tbody>` +
      (others.length
        ? '<tbody class="differences"><tr><th colspan="7" scope="rowgroup">Other models: how far each is from ' +
          `${others[0].againstLabel}. A difference, not an error: neither model approximates the other, and a ` +
          'smaller difference does not make a model better.</th></tr>' +
          `${head('difference')}${rowsOf(f, others)}</tbody>`
        : '');
    section.append(table);
    if (f.key === 'openpbr-layers' && report.materialx) section.append(materialxSection(report.materialx, f));
  }
  boxTables(root);
}
costSelect.addEventListener('change', render);

/** The nearest heading (h2, or h3 of a part) above `el` in its section: what its table's box is called. */
function headingOf(el) {
  for (let e = el.previousElementSibling; e; e = e.previousElementSibling)
    if (/^H[23]$/.test(e.tagName)) return e.textContent;
  return el.parentElement ? headingOf(el.parentElement) : 'Figures';
}

/** Each table of `within` in a box of its own that scrolls sideways: on a phone its columns are wider than the page. */
function boxTables(within) {
  for (const table of within.querySelectorAll('table:not(.table-scroll table)')) {
    const box = Object.assign(document.createElement('div'), { className: 'table-scroll', tabIndex: 0 });
    box.setAttribute('role', 'region');
    box.setAttribute('aria-label', `Table: ${headingOf(table)}`);
    table.replaceWith(box);
    box.append(table);
  }
}
render();

const ms = (x) => x.toFixed(0);
const latencyRow = (r) => row([r.widget, `<code>${r.key}</code>`, ms(r.medianMs), ms(r.worstMs)]);

/** The slowest widgets by median (those over the target, else the three slowest), named with their figures. */
function slowestWords({ rows, targetMs }) {
  const answering = rows.filter((r) => !r.progressive).sort((a, b) => b.medianMs - a.medianMs);
  const over = answering.filter((r) => r.medianMs > targetMs);
  const named = (over.length ? over : answering.slice(0, 3))
    .map((r) => `<strong>${r.widget}</strong> (${ms(r.medianMs)} ms, worst ${ms(r.worstMs)} ms)`)
    .join(', ');
  return over.length
    ? `Over the ${targetMs} ms target: ${named}.`
    : `Every widget answers within ${targetMs} ms (median; the progressive ones apart); the slowest are ${named}.`;
}

/** From a change to its frame, per widget (bench/latency.js): the widgets that answer at once, then the others. */
function renderLatency(latency) {
  const section = document.createElement('section');
  section.id = 'latency';
  const head = row(['Widget', 'dragged', 'median (ms)', 'worst (ms)'], 'th');
  const table = (rows) =>
    `<table class="data-table compact"><thead>${head}</thead><tbody>${rows.map(latencyRow).join('')}</tbody></table>`;
  const progressive = latency.rows.filter((r) => r.progressive);
  section.innerHTML =
    '<h2>From a change to its frame</h2>' +
    `<p class="domain">Each widget's main control dragged in ${latency.steps} steps, one change after the ` +
    'previous frame is done: the time from the change to its frame on screen, GPU work finished (measured ' +
    `${latency.date.slice(0, 10)}, software WebGL on two cores). ${slowestWords(latency)}</p>` +
    table(latency.rows.filter((r) => !r.progressive)) +
    (progressive.length
      ? '<p>Progressive widgets (they keep refining a Monte Carlo picture): the time to their first changed ' +
        `frame.</p>${table(progressive)}`
      : '');
  extra.after(section);
}

// three.js for scale, and what each page costs to open
const vt = report.versusThree;
const extra = document.getElementById('pages');
extra.innerHTML =
  `<h2>Against three.js</h2><p>A sphere at ${vt.size}² pixels with the terms of MeshStandardMaterial (GGX, ` +
  "height-correlated Smith, Schlick with F0 = 0.04, Lambert, one punctual light): this app's shader takes " +
  `<strong>${vt.oursMsPerFrame.toFixed(2)} ms</strong> a frame, MeshStandardMaterial ` +
  `<strong>${vt.threeMsPerFrame.toFixed(2)} ms</strong>: a ratio of <strong>${vt.ratio.toFixed(2)}</strong>.</p>` +
  '<h2>What each page loads</h2><table class="data-table compact"><thead>' +
  row(['Page', 'JavaScript (KiB, uncompressed)', 'files', 'load (ms)', 'first 3-D frame (ms)'], 'th') +
  '</thead><tbody>' +
  report.pages
    .map((p) =>
      row([
        p.page,
        p.jsKB.toFixed(0),
        p.jsFiles,
        p.loadMs.toFixed(0),
        p.firstFrameMs === null ? '—' : p.firstFrameMs.toFixed(0),
      ]),
    )
    .join('') +
  '</tbody></table>';
if (report.ibl) renderIbl(report.ibl, { anchor: extra, plots, reportDate: report.date });
if (report.latency) renderLatency(report.latency);
boxTables(extra.parentElement);
publish('performance', report);
