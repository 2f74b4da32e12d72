// Tells the parent page the result of each Check, { type: 'shading-lab:graded', id, passed, score }, when the
// exercises page is in an iframe, by the embed protocol's origin rules (src/core/framework/embed-protocol.js):
// only to an origin of `origins=` (or the page's own), known from the browser's hint or from a message the
// parent sent; never to '*'. Until the parent's origin is known and allowed, nothing is posted.
import { MESSAGE_PREFIX, parentOriginHint, parseAllowedOrigins } from '../core/framework/embed-protocol.js';

/**
 * params: the page's URL parameters. Returns { graded(result), notices }; `notices` are the problems with
 * `origins=` for the page to show.
 */
export function createGradedLink(params) {
  const { origins, notices } = parseAllowedOrigins(params.get('origins'), location.origin);
  const parent = window.parent;
  if (parent === window) return { graded() {}, notices };
  const hint = parentOriginHint();
  let parentOrigin = hint && origins.has(hint) ? hint : null;
  const onMessage = (e) => {
    const fromAllowedParent = e.source === parent && origins.has(e.origin);
    if (fromAllowedParent && typeof e.data?.type === 'string' && e.data.type.startsWith(MESSAGE_PREFIX))
      parentOrigin = e.origin;
  };
  window.addEventListener('message', onMessage);
  return {
    /** result: { id, passed, score } */
    graded({ id, passed, score }) {
      if (parentOrigin) parent.postMessage({ type: `${MESSAGE_PREFIX}graded`, id, passed, score }, parentOrigin);
    },
    notices,
  };
}
