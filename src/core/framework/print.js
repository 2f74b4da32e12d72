// Printed pages: just before the browser prints (beforeprint), every widget gets a still image of what its views
// show in its current state, with the link to that state and the link's QR code under it; the print style sheet
// (styles.css, @media print) hides the controls and the live canvases and shows the stills. The event gives no
// time to wait, so the QR module is loaded when the first widget registers and everything is drawn synchronously.
import { snapshotWidget } from './snapshot.js';

const printables = new Set(); // { root, title, getLink }
let qrcode = null;

function qrCanvas(link, title) {
  const canvas = document.createElement('canvas');
  canvas.className = 'print-qr';
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', `QR code of the link to this state of ${title}`);
  qrcode?.toCanvas(canvas, link, { width: 240, margin: 1, errorCorrectionLevel: 'M' }, () => {});
  return canvas;
}

/** The still of one widget: its views as an image, the link to its state and the QR code of the link. */
function still({ root, title, getLink }) {
  const link = getLink();
  const figure = document.createElement('figure');
  figure.className = 'print-still';
  const image = snapshotWidget(root);
  const alt = `${title}, as it was shown`;
  if (image) figure.append(Object.assign(document.createElement('img'), { src: image, alt }));
  const caption = document.createElement('figcaption');
  const text = document.createElement('span');
  text.append(`${title}, this state: `, Object.assign(document.createElement('a'), { href: link, textContent: link }));
  caption.append(qrCanvas(link, title), text);
  figure.append(caption);
  return figure;
}

function beforePrint() {
  for (const p of printables) {
    p.root.querySelector(':scope > .print-still')?.remove();
    p.root.querySelector('.widget-body')?.before(still(p));
  }
}

/** Prints `root` (a widget) as a still with its link; returns the function that takes it out again. */
export function registerPrintable(root, title, getLink) {
  if (!printables.size) {
    addEventListener('beforeprint', beforePrint);
    import('qrcode').then((m) => (qrcode = m.default));
  }
  const entry = { root, title, getLink };
  printables.add(entry);
  return () => {
    printables.delete(entry);
    if (!printables.size) removeEventListener('beforeprint', beforePrint);
  };
}
