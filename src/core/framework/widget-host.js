// Mounts a widget by name and keeps its state in the page URL (optionally under a prefix, so several
// widgets can share one page), and exposes it for tests and parent pages.
import { WIDGETS, isWidgetName } from '../../widgets/registry.js';
import { stateToParams } from './state.js';
import { createLocked } from './widget-shell.js';

const registry = (globalThis.__shadingLab ??= { frames: 0 });
registry.widgets ??= {};

/** The URL parameters that belong to a widget: all of them, or those under `prefix.`. */
export function widgetParams(search, prefix) {
  const out = new Map(); // not a plain object: a parameter named __proto__ must stay a key like any other
  for (const [k, v] of new URLSearchParams(search)) {
    if (!prefix) out.set(k, v);
    else if (k.startsWith(`${prefix}.`)) out.set(k.slice(prefix.length + 1), v);
  }
  return Object.fromEntries(out);
}

// Parameters of embed.html that are not widget state: the widget's name and the origins allowed to message it.
const EMBED_PARAMS = new Set(['w', 'origins']);

function writeUrl(schema, state, prefix) {
  const url = new URL(location.href);
  const own = stateToParams(schema, state);
  for (const k of [...url.searchParams.keys()]) {
    if (prefix ? k.startsWith(`${prefix}.`) : !EMBED_PARAMS.has(k)) url.searchParams.delete(k);
  }
  for (const [k, v] of own) url.searchParams.set(prefix ? `${prefix}.${k}` : k, v);
  history.replaceState(history.state, '', url);
}

/**
 * Creates widget `name` inside `container` with the state found in the URL.
 * options: { prefix, syncUrl = true, onStateChange, state (instead of the URL's), initialState (under what the URL
 * says), locked (keys the GUI cannot change) }
 */
export async function mountWidget(
  container,
  name,
  { prefix = '', syncUrl = true, onStateChange, options = {}, state, initialState = {}, locked = [] } = {},
) {
  if (!isWidgetName(name)) throw new Error(`unknown widget ${name}`);
  const { widget } = await WIDGETS[name].load();
  let timer = 0;
  const instance = createLocked(locked, () =>
    widget.create(container, state ?? { ...initialState, ...widgetParams(location.search, prefix) }, {
      ...options,
      onStateChange(next) {
        onStateChange?.(next);
        if (!syncUrl) return;
        clearTimeout(timer);
        timer = setTimeout(() => writeUrl(widget.schema, next, prefix), 120);
      },
    }),
  );
  registry.widgets[prefix || name] = instance;
  return instance;
}
