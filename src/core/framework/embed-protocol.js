// The postMessage protocol of embed.html: a parent page reads and sets the state of the widget in its
// iframe, and hears when the widget is ready and when the user changes it (docs/embedding.md).
//
//   parent → widget   { type: 'shading-lab:get', id? }
//                     { type: 'shading-lab:set', state: { key: value, ... }, id? }
//                     { type: 'shading-lab:snapshot', id? }
//   widget → parent   { type: 'shading-lab:ready', widget, state, query }        once mounted
//                     { type: 'shading-lab:state', id, widget, state, query }    reply to get and to set
//                     { type: 'shading-lab:error', id, widget, errors, state }   set had bad values (kept the good
//                                                                                state)
//                     { type: 'shading-lab:changed', widget, state, query }      the user changed it (debounced)
//                     { type: 'shading-lab:snapshot', id, widget, state, query, image }  reply: a PNG data URL
//                     { type: 'shading-lab:resize', widget, height }    the content's height in CSS px: on ready
//                                                                       and whenever it changes
//
// `query` is the state as embed URL parameters (only what differs from the defaults). Messages are taken only
// from the parent window and from an allowed origin; anything else, or of another shape, is ignored. Replies
// go to the origin that asked, never to '*'.
import { fieldOf, stateToParams } from './state.js';
import { STATE_NOTICES } from './notice.js';

export const MESSAGE_PREFIX = 'shading-lab:';
export const CHANGED_DEBOUNCE_MS = 150;
const MAX_ID_LENGTH = 200;

const cut = (key) => (key.length > 60 ? `${key.slice(0, 60)}… (${key.length} characters)` : key); // a key echoed back
const isPlainObject = (x) => x !== null && typeof x === 'object' && Object.getPrototypeOf(x) === Object.prototype;
const isId = (id) => id === undefined || (typeof id === 'string' && id.length <= MAX_ID_LENGTH) || Number.isFinite(id);

/**
 * The origins allowed to message the widget, from the `origins=` parameter (a comma list of origins such as
 * https://slides.example.org). The widget's own origin is always allowed. Returns { origins: Set, notices }.
 */
export function parseAllowedOrigins(param, ownOrigin) {
  const origins = new Set([ownOrigin]);
  const notices = [];
  for (const item of (param ?? '')
    .split(',')
    .map((s) => s.trim())
    .filter(Boolean)) {
    let origin = null;
    try {
      const url = new URL(item);
      if ((url.protocol === 'https:' || url.protocol === 'http:') && url.pathname === '/' && !url.search && !url.hash)
        origin = url.origin;
    } catch {
      /* not a URL: reported below */
    }
    if (origin) origins.add(origin);
    else notices.push(`origins: “${item}” is not an origin like https://example.org; ignored.`);
  }
  return { origins, notices };
}

/** A message from the parent as { kind: 'get' | 'set' | 'snapshot', id, state }, or null when it has another shape. */
export function parseMessage(data) {
  if (!isPlainObject(data) || typeof data.type !== 'string' || !isId(data.id)) return null;
  if (data.type === `${MESSAGE_PREFIX}get`) return { kind: 'get', id: data.id };
  if (data.type === `${MESSAGE_PREFIX}snapshot`) return { kind: 'snapshot', id: data.id };
  if (data.type === `${MESSAGE_PREFIX}set` && isPlainObject(data.state))
    return { kind: 'set', id: data.id, state: data.state };
  return null;
}

/** One notice for any number of unknown keys: the first four named (cut short), the rest counted. */
function unknownKeysNotice(schema, unknown) {
  const named = unknown
    .slice(0, 4)
    .map((k) => `“${cut(k)}”`)
    .join(', ');
  const more = unknown.length > 4 ? ` and ${unknown.length - 4} more` : '';
  const verb = unknown.length > 1 ? 'are not settings' : 'is not a setting';
  return `${named}${more} ${verb} of this widget (it has: ${Object.keys(schema).join(', ')}); ignored.`;
}

/** The notice for the keys of `partial` that are no setting of the widget (ignored), or none. */
export function unknownKeys(schema, partial) {
  const unknown = Object.keys(partial).filter((k) => !Object.hasOwn(schema, fieldOf(schema, k, partial[k])));
  return unknown.length ? [unknownKeysNotice(schema, unknown)] : [];
}

/**
 * Applies a parent's `partial` through the widget's own update, the one place a state is coerced (locked keys
 * left out there), and returns what the parent is told: the notices of that coercion (`widgetRoot` sends them,
 * STATE_NOTICES), then the unknown keys.
 */
function applyFromParent({ schema, instance, notices, widgetRoot }, partial) {
  const unknown = unknownKeys(schema, partial);
  if (unknown.length) notices.show(unknown); // the widget shows the invalid values itself
  const invalid = [];
  const hear = (/** @type {CustomEvent} */ e) => invalid.push(...e.detail);
  widgetRoot.addEventListener(STATE_NOTICES, hear);
  try {
    instance.update(partial);
  } finally {
    widgetRoot.removeEventListener(STATE_NOTICES, hear);
  }
  return [...invalid, ...unknown];
}

/** The parent's origin, when the browser tells it (ancestorOrigins, else the referrer). */
export function parentOriginHint() {
  const ancestor = location.ancestorOrigins?.[0];
  if (ancestor) return ancestor;
  try {
    return document.referrer ? new URL(document.referrer).origin : null;
  } catch {
    return null;
  }
}

/** The height of `content` with its margins, whole CSS pixels (rounded up: a frame that tall has no scroll bar). */
export function contentHeight(content) {
  const style = getComputedStyle(content);
  const margins = Number.parseFloat(style.marginTop) + Number.parseFloat(style.marginBottom);
  return Math.ceil(content.getBoundingClientRect().height + (margins || 0));
}

/**
 * Connects a mounted widget to its parent window. `instance` is the widget ({ update, getState }), `widgetRoot`
 * the element that holds it (it hears the widget's STATE_NOTICES there), `notices` a notice area for problems
 * the widget itself does not report (unknown keys), `capture()` the picture it
 * shows as a PNG data URL (or null), `content` the element whose height the parent is told (`resize`, observed
 * with a ResizeObserver; none when omitted). Returns
 * { ready(), userChanged() (call on every state change), dispose() }.
 */
export function connectEmbedProtocol({
  name,
  schema,
  instance,
  widgetRoot,
  origins,
  notices,
  capture = () => null,
  content = null,
  parent = window.parent,
}) {
  const hint = parentOriginHint();
  let parentOrigin = hint && origins.has(hint) ? hint : null; // where unsolicited messages go; null: nowhere yet
  let fromParent = false; // true while a `set` is applied: that is not a user change
  let timer = 0;

  const snapshot = () => {
    const state = instance.getState();
    return { widget: name, state: structuredClone(state), query: stateToParams(schema, state).toString() };
  };
  const post = (type, origin, fields = {}) =>
    parent.postMessage({ type: `${MESSAGE_PREFIX}${type}`, ...snapshot(), ...fields }, origin);

  // the height goes, like every unsolicited message, only to the parent's origin once it is known and allowed
  let told = { origin: null, height: -1 };
  const tellHeight = () => {
    if (!content || !parentOrigin) return;
    const height = contentHeight(content);
    if (told.origin === parentOrigin && told.height === height) return;
    told = { origin: parentOrigin, height };
    parent.postMessage({ type: `${MESSAGE_PREFIX}resize`, widget: name, height }, parentOrigin);
  };
  const observer = content && new ResizeObserver(tellHeight);

  const onMessage = (e) => {
    if (e.source !== parent || !origins.has(e.origin)) return;
    const msg = parseMessage(e.data);
    if (!msg) return;
    parentOrigin = e.origin;
    tellHeight(); // a parent heard from first (its browser hid its origin) learns the height now
    if (msg.kind === 'snapshot') return void post('snapshot', e.origin, { id: msg.id, image: capture() });
    if (msg.kind === 'set') {
      fromParent = true;
      let errors;
      try {
        errors = applyFromParent({ schema, instance, notices, widgetRoot }, msg.state);
      } finally {
        fromParent = false;
      }
      if (errors.length) post('error', e.origin, { id: msg.id, errors });
    }
    post('state', e.origin, { id: msg.id });
  };
  window.addEventListener('message', onMessage);

  return {
    ready() {
      if (parentOrigin) post('ready', parentOrigin);
      observer?.observe(content); // its first call sends the height
    },
    userChanged() {
      if (fromParent || !parentOrigin) return;
      clearTimeout(timer);
      timer = setTimeout(() => parentOrigin && post('changed', parentOrigin), CHANGED_DEBOUNCE_MS);
    },
    dispose() {
      clearTimeout(timer);
      observer?.disconnect();
      window.removeEventListener('message', onMessage);
    },
  };
}
