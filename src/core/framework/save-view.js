// @ts-check
// Every described view can be saved as PNG: a small button in the top-right corner of its canvas (CSS anchor
// positioning, styles.css `.save-view`), reached by Tab right after the canvas, named for what the view shows.
// A WebGL view keeps no frame after it is shown, so the still is taken by snapshot.js, which redraws it first.
import { stillOf } from './snapshot.js';
import { download } from './download.js';

const MAX_NAME = 60; // characters of the view's description that name its button and its file
const buttons = new WeakMap(); // canvas → its save button
let anchors = 0; // each canvas gets an anchor name of its own

/**
 * What a description names, for the button and the file: its first clause, cut short.
 * @param {string} text
 */
export function viewName(text) {
  const first = text.split(/:|\.(?:\s|$)|;/)[0].trim();
  return first.length > MAX_NAME ? `${first.slice(0, MAX_NAME - 1).trimEnd()}…` : first;
}

/**
 * A file name: the widget's and the view's names, lower case, runs of anything but letters and digits as '-'.
 * @param {string} widget
 * @param {string} view
 */
export function pngFileName(widget, view) {
  const slug = `${widget} ${view}`
    .toLowerCase()
    .replace(/[^\p{L}\p{N}]+/gu, '-')
    .replace(/^-|-$/g, '');
  return `${slug || 'view'}.png`;
}

/** @param {HTMLCanvasElement} canvas */
function save(canvas) {
  const still = canvas.width && canvas.height ? stillOf(canvas) : null;
  if (!still) return;
  const widget = /** @type {HTMLElement | null} */ (canvas.closest('[data-widget]'))?.dataset.widget ?? 'shading-lab';
  const file = pngFileName(widget, viewName(canvas.getAttribute('aria-label') ?? ''));
  still.toBlob((blob) => blob && download(file, blob), 'image/png');
}

const SVG = 'http://www.w3.org/2000/svg';

/** A download arrow over a tray, drawn in the button's text colour. */
function icon() {
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('viewBox', '0 0 16 16');
  svg.setAttribute('aria-hidden', 'true');
  const path = document.createElementNS(SVG, 'path');
  path.setAttribute('d', 'M8 2v8M4.5 6.5 8 10l3.5-3.5M2.5 11.5v2h11v-2');
  svg.append(path);
  return svg;
}

/** @param {HTMLCanvasElement} canvas */
function createButton(canvas) {
  const button = document.createElement('button');
  button.type = 'button';
  button.className = 'save-view';
  button.title = 'Save this view as PNG';
  button.append(icon());
  const anchor = `--save-view-${++anchors}`;
  canvas.style.setProperty('anchor-name', anchor);
  button.style.setProperty('position-anchor', anchor);
  button.addEventListener('click', () => save(canvas));
  canvas.after(button);
  return button;
}

/**
 * Gives `canvas` a save button (once) and names it for `text`, the view's description.
 * @param {HTMLCanvasElement} canvas
 * @param {string} text
 */
export function offerSave(canvas, text) {
  if (!buttons.has(canvas) && !canvas.parentElement) return; // not on the page yet: the next description adds it
  const button = buttons.get(canvas) ?? createButton(canvas);
  buttons.set(canvas, button);
  button.setAttribute('aria-label', `Save image (PNG): ${viewName(text)}`);
}
