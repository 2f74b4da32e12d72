// parity.html: runs the GLSL-vs-JS parity harness on this browser's GPU, shows the table and a report to send.
import '../styles.css';
import * as THREE from 'three';
import { PARITY_CASES, TOLERANCE } from '../core/gpu/parity-cases.js';
import { runParity } from '../core/gpu/parity.js';
import { parityReport, rendererInfo } from '../core/gpu/parity-report.js';
import { download } from '../core/framework/download.js';
import { showBlockingMessage } from '../core/framework/notice.js';
import { publish } from '../core/framework/debug-hooks.js';

const out = document.getElementById('parity');

function summaryLine(results) {
  const failed = results.filter((r) => !r.pass);
  const summary = document.createElement('p');
  summary.className = `parity-summary ${failed.length ? 'fail' : 'pass'}`;
  summary.id = 'parity-summary';
  summary.textContent = failed.length
    ? `${failed.length} of ${results.length} functions differ from the reference beyond tolerance.`
    : `All ${results.length} functions match the float64 reference within |g − j| ≤ ${TOLERANCE.atol} + ` +
      `${TOLERANCE.rtol}·|j| (or the looser tolerance shown in their row), with no NaN, Inf or out-of-range value.`;
  return summary;
}

function resultsTable(results) {
  const table = document.createElement('table');
  table.className = 'data-table';
  table.innerHTML =
    '<thead><tr><th>Function</th><th>Inputs</th><th>Max abs error</th><th>Max rel error</th><th>Worst input ' +
    '(float32)</th><th>GPU / JS there</th><th>Beyond tol.</th><th>NaN/Inf/out of range</th></tr></thead>';
  const body = table.createTBody();
  const anchored = new Set();
  for (const r of results) {
    const tr = body.insertRow();
    const own = r.tolerance.rtol !== TOLERANCE.rtol ? ` (rtol ${r.tolerance.rtol})` : '';
    const cells = [
      `${r.name}${own}`,
      r.count,
      r.maxAbs.toExponential(2),
      r.maxRel.toExponential(2),
      r.worst.args.map((x) => x.toPrecision(7)).join(', '),
      `${r.worst.gpu.toPrecision(7)} / ${r.worst.js.toPrecision(7)}`,
      r.failures,
      r.invalid,
    ];
    cells.forEach((c) => (tr.insertCell().textContent = c));
    tr.className = r.pass ? '' : 'fail';
    const fn = r.name.split(' ')[0]; // the widgets' "terms used" links land on the first row of each function
    if (!anchored.has(fn)) {
      anchored.add(fn);
      tr.id = `fn-${fn}`;
    }
  }
  const scroll = document.createElement('div');
  scroll.className = 'table-scroll';
  scroll.tabIndex = 0; // a scrolling region is reachable by keyboard (narrower than the table, it scrolls)
  scroll.setAttribute('role', 'region');
  scroll.setAttribute('aria-label', 'Each function on the GPU against float64');
  scroll.append(table);
  return scroll;
}

/** The report as text, with buttons to copy it and to save it as a file, and the text itself to read. */
function reportSection(text, gpu) {
  const section = document.createElement('section');
  section.className = 'parity-report';
  section.setAttribute('aria-labelledby', 'parity-report-h');
  section.innerHTML =
    '<h2 id="parity-report-h">Report</h2><p>Measured on <strong></strong>. To add your GPU to the ones measured, ' +
    'copy or save this report and send it to the people who keep this copy of Shading Lab (as a new issue, where ' +
    'the project takes them).</p>';
  section.querySelector('strong').textContent = gpu.renderer;
  const area = Object.assign(document.createElement('textarea'), { id: 'parity-report', readOnly: true, value: text });
  area.rows = 8;
  area.setAttribute('aria-label', 'Parity report');
  const status = Object.assign(document.createElement('span'), { className: 'parity-report-status' });
  status.setAttribute('role', 'status');
  const button = (label, onClick) =>
    Object.assign(document.createElement('button'), { type: 'button', textContent: label, onclick: onClick });
  const copy = async () => {
    try {
      await navigator.clipboard.writeText(text);
      status.textContent = 'Copied.';
    } catch {
      // no clipboard access (an insecure origin, or permission refused): leave the text selected for Ctrl+C
      area.focus();
      area.select();
      status.textContent = 'Selected: press Ctrl+C (⌘C) to copy.';
    }
  };
  const save = () => download('shading-lab-parity.txt', new Blob([text], { type: 'text/plain' }));
  const bar = Object.assign(document.createElement('div'), { className: 'toolbar' });
  bar.append(button('Copy report', copy), button('Save report', save), status);
  section.append(bar, area);
  return section;
}

const canvas = document.createElement('canvas');
const gl = canvas.getContext('webgl2');
if (!gl || !gl.getExtension('EXT_color_buffer_float')) {
  showBlockingMessage(
    out,
    'This check needs WebGL2 with float render targets.',
    'Your browser did not provide them, so the shaders cannot be compared here.',
  );
} else {
  const gpu = rendererInfo(gl);
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl });
  // ?only=name1,name2 runs the rows whose names start with one of those (a quick check of a few functions)
  const only = new URLSearchParams(location.search).get('only')?.split(',').filter(Boolean);
  const results = runParity(
    renderer,
    only ? PARITY_CASES.filter((c) => only.some((o) => c.name.startsWith(o))) : PARITY_CASES,
  );
  renderer.dispose();
  const report = parityReport(results, { ...gpu, url: location.href, browser: navigator.userAgent, date: new Date() });
  publish('parity', results);
  publish('parityReport', { ...gpu, text: report });
  out.append(summaryLine(results), reportSection(report, gpu), resultsTable(results));
}
