// Save what a view shows: an image as PNG, its data as CSV.
import { download } from '../framework/download.js';

export function canvasToPng(canvas, filename) {
  canvas.toBlob((blob) => blob && download(filename, blob), 'image/png');
}

const csvCell = (v) => (typeof v === 'number' ? String(v) : `"${String(v).replaceAll('"', '""')}"`);

/** columns: [{ name, values }], all of one length. */
export function columnsToCsv(columns) {
  const rows = [columns.map((c) => csvCell(c.name)).join(',')];
  const n = columns[0]?.values.length ?? 0;
  for (let i = 0; i < n; i++) rows.push(columns.map((c) => csvCell(c.values[i])).join(','));
  return `${rows.join('\n')}\n`;
}

export function downloadCsv(columns, filename) {
  download(filename, new Blob([columnsToCsv(columns)], { type: 'text/csv' }));
}

/** A small toolbar of export buttons: [{ label, onClick }]. */
export function createToolbar(container, actions) {
  const bar = document.createElement('div');
  bar.className = 'toolbar';
  for (const { label, onClick, title } of actions) {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = label;
    if (title) b.title = title;
    b.addEventListener('click', onClick);
    bar.append(b);
  }
  container.append(bar);
  return bar;
}
