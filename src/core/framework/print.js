// Printed pages: just before the browser prints (beforeprint), every canvas of a widget's views gets a still image
// of its frame, put where the canvas sits (a plot's title stays above its plot, its legend below), and the widget
// gets the link to its state with the link's QR code under its views; the print style sheet (styles.css,
// @media print) hides the controls and the live canvases and shows the stills. The event gives no time to wait,
// so the QR module is loaded when the first widget registers and everything is drawn synchronously.
import { stillOf } from './snapshot.js';
import { whileLoading } from './debug-hooks.js';

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

/** The link to the widget's state and its QR code, as printed under the widget's views. */
function printLink(title, link) {
  const p = document.createElement('p');
  p.className = 'print-link';
  const text = document.createElement('span');
  text.append(
    `${title} in this state: `,
    Object.assign(document.createElement('a'), { href: link, textContent: link }),
  );
  p.append(qrCanvas(link, title), text);
  return p;
}

/**
 * A still image of `canvas` as shown (its CSS size), to print in its place: after the element the print style
 * sheet hides with it (a 3-D view's viewport, a plot's uPlot wrapper), or after the canvas itself.
 */
function placeStill(canvas, title) {
  const { width, height } = canvas.getBoundingClientRect();
  const img = Object.assign(document.createElement('img'), {
    className: 'print-canvas',
    src: stillOf(canvas).toDataURL('image/png'),
    alt: `${title}, as it was shown`,
  });
  img.style.cssText = `width: ${Math.round(width)}px; aspect-ratio: ${width} / ${height}`;
  (canvas.closest('.viewport, .u-wrap') ?? canvas).after(img);
}

function beforePrint() {
  for (const { root, title, getLink } of printables) {
    root.querySelectorAll('.print-canvas, .print-link').forEach((el) => el.remove());
    const view = root.querySelector('.widget-view') ?? root;
    const canvases = [...view.querySelectorAll('canvas')].filter(
      (c) => c.width && c.height && c.getClientRects().length,
    );
    canvases.forEach((canvas) => placeStill(canvas, title));
    root.querySelector('.widget-body')?.after(printLink(title, getLink()));
  }
}

/** Prints `root` (a widget) as stills of its views with its link; returns the function that takes it out again. */
export function registerPrintable(root, title, getLink) {
  if (!printables.size) {
    addEventListener('beforeprint', beforePrint);
    whileLoading(import('qrcode')).then((m) => (qrcode = m.default));
  }
  const entry = { root, title, getLink };
  printables.add(entry);
  return () => {
    printables.delete(entry);
    if (!printables.size) removeEventListener('beforeprint', beforePrint);
  };
}
