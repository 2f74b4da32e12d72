// The Web Worker that keeps the page responsive: it parses a dropped MERL file (35 MB), writes the synthetic
// examples, fits the five models and tabulates a fit for the GPU, reporting progress as it goes.
// Messages in: { id, type: 'parse', buffer } | { id, type: 'synthesize', model, params } |
//   { id, type: 'fit', models, options } | { id, type: 'tabulate', model, params }.
// Messages out: { id, type: 'loaded', table, half, missing, ms } |
//   { id, type: 'progress', model, index, evaluations, error } | { id, type: 'fitted', index, result, ms } |
//   { id, type: 'tabulated', half } | { id, type: 'done' } | { id, type: 'error', message }.
import { DataUtils } from 'three';
import { parseMerl } from './merl.js';
import { fitModels, synthesizeTable } from './fit.js';

let measured = null;

/** The table as RGBA half floats in the MERL order (phi_d fastest): the GPU's 3-D texture. */
function halfFloatRgba(table) {
  const n = table.length / 3;
  const out = new Uint16Array(4 * n);
  const one = DataUtils.toHalfFloat(1);
  for (let s = 0; s < n; s++) {
    for (let c = 0; c < 3; c++) out[4 * s + c] = DataUtils.toHalfFloat(Math.min(Math.max(table[c * n + s], 0), 65000));
    out[4 * s + 3] = one;
  }
  return out;
}

function load(next, id, started) {
  measured = next; // only a file that parsed replaces the last one
  const table = next.table.slice();
  const half = halfFloatRgba(next.table);
  self.postMessage({ id, type: 'loaded', table, half, missing: next.missing, ms: performance.now() - started }, [
    table.buffer,
    half.buffer,
  ]);
}

const handlers = {
  parse: (msg, started) => load(parseMerl(msg.buffer), msg.id, started),
  synthesize: (msg, started) => load(synthesizeTable(msg.model, msg.params), msg.id, started),
  fit(msg) {
    if (!measured) throw new Error('No measured BRDF is loaded.');
    fitModels(measured, msg.models, msg.options, {
      onProgress: (p, index) => self.postMessage({ id: msg.id, type: 'progress', index, ...p }),
      onFitted: (result, index, ms) => self.postMessage({ id: msg.id, type: 'fitted', index, result, ms }),
    });
  },
  tabulate(msg) {
    const half = halfFloatRgba(synthesizeTable(msg.model, msg.params).table);
    self.postMessage({ id: msg.id, type: 'tabulated', half }, [half.buffer]);
  },
};

self.onmessage = ({ data: msg }) => {
  try {
    handlers[msg.type](msg, performance.now());
    self.postMessage({ id: msg.id, type: 'done' });
  } catch (e) {
    self.postMessage({ id: msg.id, type: 'error', message: e.message });
  }
};
