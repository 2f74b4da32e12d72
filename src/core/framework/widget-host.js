// @ts-check
// Mounts a widget by name and keeps its state in the page URL (optionally under a prefix, so several
// widgets can share one page), and exposes it for tests and parent pages. The widgets come from the registry
// the page hands in (src/widgets/registry.js): the framework itself imports no widget.
import { currentNames, stateToParams } from './state.js';
import { cancelLater, later, registerWidget, whileLoading } from './debug-hooks.js';

/** @typedef {import('./types.js').WidgetRegistry} WidgetRegistry */
/** @typedef {import('./types.js').Widget} Widget */
/** @typedef {import('./types.js').Schema} Schema */
/** @typedef {import('./types.js').State} State */

/**
 * The URL parameters that belong to a widget: all of them, or those under `prefix.`.
 * @param {string} search
 * @param {string} [prefix]
 * @returns {Record<string, string>}
 */
export function widgetParams(search, prefix) {
  const out = new Map(); // not a plain object: a parameter named __proto__ must stay a key like any other
  for (const [k, v] of new URLSearchParams(search)) {
    if (!prefix) out.set(k, v);
    else if (k.startsWith(`${prefix}.`)) out.set(k.slice(prefix.length + 1), v);
  }
  return Object.fromEntries(out);
}

// Parameters of embed.html that are not widget state: the widget's name, the origins allowed to message it, the
// presenter view and the locked keys.
const EMBED_PARAMS = new Set(['w', 'origins', 'presenter', 'locked']);

/**
 * The page's URL `href` with a widget's state in it (its keys under `prefix.`, or all but the embed's own).
 * @param {string} href
 * @param {Schema} schema
 * @param {State} state
 * @param {string} prefix
 */
export function urlWithState(href, schema, state, prefix) {
  const url = new URL(href);
  const own = stateToParams(schema, state);
  for (const k of [...url.searchParams.keys()]) {
    if (prefix ? k.startsWith(`${prefix}.`) : !EMBED_PARAMS.has(k)) url.searchParams.delete(k);
  }
  for (const [k, v] of own) url.searchParams.set(prefix ? `${prefix}.${k}` : k, v);
  return url;
}

/**
 * @param {Schema} schema
 * @param {State} state
 * @param {string} prefix
 */
function writeUrl(schema, state, prefix) {
  history.replaceState(history.state, '', urlWithState(location.href, schema, state, prefix));
}

/**
 * @typedef {object} MountOptions
 * @property {WidgetRegistry} widgets  the widgets by name (the page passes src/widgets/registry.js's WIDGETS)
 * @property {string} [prefix]  the widget's URL parameters are `prefix.key` (several widgets on one page); also
 *   its key in the test hooks (else its name)
 * @property {boolean} [syncUrl]  write the state into the URL as it changes (default true)
 * @property {(state: State) => void} [onStateChange]  called after each change that took
 * @property {Partial<Record<string, unknown>>} [state]  the state to start from, instead of the URL's
 * @property {Partial<Record<string, unknown>>} [initialState]  under what the URL says
 * @property {string[]} [locked]  keys the GUI and update() cannot change (an exercise fixes them)
 * @property {import('./types.js').WidgetOptions} [options]  the widget's own options (f0-tables' onPick)
 */

/**
 * Creates widget `name` inside `container` with the state found in the URL. Returns the instance and the
 * widget's module (its name, schema and create) it was made from. The mount is pending work in the test hooks from
 * now until its first frame (whileLoading): its chunk may take a while to arrive.
 * @param {HTMLElement} container
 * @param {string} name
 * @param {MountOptions} options
 * @returns {Promise<{ instance: Widget, widget: import('./types.js').WidgetContract }>}
 */
export const mountWidget = (container, name, options) => whileLoading(mount(container, name, options));

/**
 * @param {HTMLElement} container
 * @param {string} name
 * @param {MountOptions} options
 * @returns {Promise<{ instance: Widget, widget: import('./types.js').WidgetContract }>}
 */
async function mount(
  container,
  name,
  { widgets, prefix = '', syncUrl = true, onStateChange, options = {}, state, initialState = {}, locked = [] },
) {
  if (!Object.hasOwn(widgets, name)) throw new Error(`unknown widget ${name}`);
  const { widget } = await widgets[name].load();
  // the page's URL carries this widget's state (under this prefix): its Share can link to the page as it is
  if (syncUrl) container.dataset.stateInUrl = prefix;
  /** @type {number | undefined} */
  let timer;
  // old names under current ones before the two merge: a link's old key still overrides the page's current one
  const named = (/** @type {Partial<Record<string, unknown>>} */ input) => currentNames(widget.schema, input);
  const first = state ?? { ...named(initialState), ...named(widgetParams(location.search, prefix)) };
  const instance = widget.create(container, first, {
    ...options,
    locked,
    onStateChange(next) {
      onStateChange?.(next);
      if (!syncUrl) return;
      cancelLater(timer);
      timer = later(() => writeUrl(widget.schema, next, prefix), 120);
    },
  });
  registerWidget(prefix || name, instance);
  return { instance, widget };
}
