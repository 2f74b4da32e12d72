// @ts-check
// Words for what a widget draws, for people who cannot see it. Every canvas carries role="img" and an
// aria-label that is rewritten whenever the picture changes; each widget also has one visually hidden
// live region that reads out a short summary after the state settles (not on every step of a drag).
import { offerSave } from './save-view.js';
import { cancelLater, later } from './debug-hooks.js';

/**
 * Marks `canvas` as an image, sets its text description and offers to save it as PNG (save-view.js), unless
 * `save` is false: a view with a PNG export of its own (a plot), or a control drawn on a canvas (a light pad).
 * @param {HTMLCanvasElement | null | undefined} canvas
 * @param {string} text
 * @param {{ save?: boolean }} [options]
 */
export function describeCanvas(canvas, text, { save = true } = {}) {
  if (!canvas) return;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', text);
  if (save) offerSave(canvas, text);
}

const SETTLE_MS = 500; // a slider drag announces once, when it stops

/**
 * A visually hidden polite live region inside `parent`; say(text) updates it once changes settle.
 * @param {HTMLElement} parent
 */
export function createLiveRegion(parent) {
  const region = document.createElement('div');
  region.className = 'visually-hidden widget-live';
  region.setAttribute('role', 'status');
  region.setAttribute('aria-live', 'polite');
  parent.append(region);
  /** @type {number | undefined} */
  let timer;
  /** @type {string | null} */
  let pending = null;
  return {
    element: region,
    /** @param {string} text */
    say(text) {
      if (text === pending) return; // the same words again (a converging view redraws): keep the timer running
      pending = text;
      if (!region.textContent) {
        region.textContent = text; // the first description is there at once (read with the widget)
        return;
      }
      cancelLater(timer);
      timer = later(() => {
        if (region.textContent !== pending) region.textContent = pending;
      }, SETTLE_MS);
    },
    dispose() {
      cancelLater(timer);
    },
  };
}

/**
 * Numbers in descriptions: 3 significant digits, no exponent for ordinary magnitudes.
 * @param {number} x
 */
export function spokenNumber(x) {
  if (!Number.isFinite(x)) return String(x);
  const a = Math.abs(x);
  if (a !== 0 && (a < 1e-3 || a >= 1e5)) return x.toExponential(2);
  return String(Number(x.toPrecision(3)));
}
