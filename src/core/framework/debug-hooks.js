// @ts-check
// globalThis.__shadingLab: what the app shows tests, benchmarks and the console. This module is the only one
// that creates or writes it; everyone else calls the functions below. It is made on first use and reuses an
// object already there, so a test or benchmark may seed it before the page loads (bench/pages.js puts a
// setter on `frames` to time the first frame).
// (The WebGL context budget that same-origin frames share, window.__shadingLabGl, is gl-budget.js's state.)

/**
 * @typedef {object} TourHook  the tour step shown (tour.html)
 * @property {number} index  the step's place in the tour
 * @property {string} id  its id (tour.html#id)
 * @property {boolean} ready  true once its widget is up
 * @property {string} [widget]  the widget's name, once ready
 * @property {import('./types.js').Widget} [instance]  the widget, once ready
 */

/**
 * @typedef {object} ExerciseHook  the exercise shown (exercises.html)
 * @property {string} id  its id
 * @property {unknown} hidden  what a hidden question drew (for tests to answer it)
 * @property {boolean} ready  true once its widget and answer are up
 */

/**
 * @typedef {object} ShadingLabHooks
 * @property {number} frames  frames the render loops have drawn, all views together
 * @property {Record<string, import('./types.js').Widget>} widgets  mounted widgets, by prefix or else name
 * @property {TourHook} [tour]
 * @property {ExerciseHook} [exercise]
 * @property {object[]} [parity]  the parity page's rows (src/core/gpu/parity.js results)
 * @property {object} [parityReport]  the parity page's GPU (vendor, renderer) and its report's text
 * @property {object} [performance]  the performance page's report (published from bench/results)
 * @property {{ ready: boolean, announced: boolean }} [offline]  the build is saved on the device; whether this
 *   page said so (only the first time on a device)
 */

/** @returns {ShadingLabHooks} */
function hooks() {
  const global = /** @type {{ __shadingLab?: Partial<ShadingLabHooks> }} */ (globalThis);
  const lab = (global.__shadingLab ??= {});
  lab.frames ??= 0;
  lab.widgets ??= {};
  return /** @type {ShadingLabHooks} */ (lab);
}

/** Counts one frame drawn by a render loop. */
export function countFrame() {
  hooks().frames++;
}

/**
 * Lists a mounted widget under `key` (its prefix, else its name).
 * @param {string} key
 * @param {import('./types.js').Widget} widget
 */
export function registerWidget(key, widget) {
  hooks().widgets[key] = widget;
}

/** @param {string} key */
export function unregisterWidget(key) {
  delete hooks().widgets[key];
}

/**
 * The widget mounted on this page under `key`, if any.
 * @param {string} key
 * @returns {import('./types.js').Widget | undefined}
 */
export function mountedWidget(key) {
  return Object.hasOwn(hooks().widgets, key) ? hooks().widgets[key] : undefined;
}

/**
 * Publishes what a page has to report (the tour's step, the exercise, the parity rows and report, the performance
 * report, the offline copy), replacing what it said before.
 * @template {'tour' | 'exercise' | 'parity' | 'parityReport' | 'performance' | 'offline'} K
 * @param {K} name
 * @param {ShadingLabHooks[K]} value
 */
export function publish(name, value) {
  hooks()[name] = value;
}
