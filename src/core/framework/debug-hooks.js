// @ts-check
// globalThis.__shadingLab: what the app shows tests, benchmarks and the console. This module is the only one
// that creates or writes it; everyone else calls the functions below. It is made when this module first runs (every
// page loads it at boot, with offline.js), so a page with no widget has it too, and reuses an object already there,
// so a test or benchmark may seed it before the page loads (bench/pages.js puts a setter on `frames` to time the
// first frame).
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
 * @property {number} [maxSamples]  a cap on the samples progressive views refine to (sampleTarget), seeded by a
 *   test before the page loads where it needs a picture drawn, not converged
 * @property {number} pending  work asked for and not yet done: animation frames the render loops requested, the
 *   app's timed pauses (requestFrame, later) and the `loading`; 0 when the page is idle (a test waits for it
 *   instead of a time)
 * @property {number} loading  chunks being fetched and widgets being mounted (whileLoading), each until the frame
 *   after it settled; 0 once the page has every module it asked for and every widget it mounts is up (or failed)
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
  lab.pending ??= 0;
  lab.loading ??= 0;
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

// Work under way, by kind: the ids of requestAnimationFrame and setTimeout are counted apart (they may coincide),
// and the loads by a token each.
const waiting = { frames: new Set(), timers: new Set(), loads: new Set() };
const publishPending = () => {
  const lab = hooks();
  lab.loading = waiting.loads.size;
  lab.pending = waiting.frames.size + waiting.timers.size + waiting.loads.size;
};
hooks(); // at boot: a page's wait for idle sees its hooks before anything asks for a frame

/**
 * requestAnimationFrame, counted in `pending` until the callback runs (a render loop's next frame).
 * @param {FrameRequestCallback} callback
 * @returns {number}
 */
export function requestFrame(callback) {
  const id = requestAnimationFrame((time) => {
    waiting.frames.delete(id);
    publishPending();
    callback(time);
  });
  waiting.frames.add(id);
  publishPending();
  return id;
}

/** @param {number} id  from requestFrame */
export function cancelFrame(id) {
  cancelAnimationFrame(id);
  waiting.frames.delete(id);
  publishPending();
}

/**
 * setTimeout, counted in `pending` until the callback runs: a pause the app waits out before it acts (an edit's
 * pause in typing, the figures after a drag), which a test waits out through `pending` rather than by a time.
 * @param {() => void} callback
 * @param {number} ms
 * @returns {number}
 */
export function later(callback, ms) {
  const id = setTimeout(() => {
    waiting.timers.delete(id);
    publishPending();
    callback();
  }, ms);
  waiting.timers.add(id);
  publishPending();
  return id;
}

/** @param {number | undefined} id  from later */
export function cancelLater(id) {
  if (id === undefined) return;
  clearTimeout(id);
  waiting.timers.delete(id);
  publishPending();
}

/**
 * Counts `work` in `pending` and `loading` from now until it settles and the animation frame after that has run: a
 * chunk fetched on demand (import()), a widget's mount (its chunk, its create, its first frame). A page that is still
 * fetching what it shows is not idle, though it has asked for no frame yet. Returns `work`.
 * @template T
 * @param {Promise<T>} work
 * @returns {Promise<T>}
 */
export function whileLoading(work) {
  const token = {};
  waiting.loads.add(token);
  publishPending();
  const done = () => {
    requestFrame(() => {}); // asked before the load is let go: `pending` does not touch 0 between the two
    waiting.loads.delete(token);
    publishPending();
  };
  work.then(done, done);
  return work;
}

/**
 * The samples a progressive view refines to: `wanted`, or `maxSamples` if a test seeded a lower cap.
 * @param {number} wanted
 */
export function sampleTarget(wanted) {
  const cap = hooks().maxSamples;
  return typeof cap === 'number' && cap > 0 ? Math.min(wanted, cap) : wanted;
}
