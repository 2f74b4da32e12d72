// Browsers cap the live WebGL contexts of a page (Chromium: 16 per renderer process). One more and the
// browser kills the oldest ("WARNING: Too many active WebGL contexts") and its canvas goes blank for good.
// So every 3-D view holds a slot of one budget, kept below that cap. A view that needs a slot and finds
// none free takes it from the view that has been out of sight the longest: that one gives its context up
// (WEBGL_lose_context) and asks for it back when it scrolls into view again.
//
// Same-origin frames (a gallery of embeds) share one budget: it lives on the topmost same-origin window.
// Only plain data is shared; the logic below runs in each frame's own realm.

export const GL_CONTEXT_BUDGET = 12; // of Chromium's 16, leaving room for a parity page or another tab

function budgetHost() {
  let host = window;
  try {
    while (host.parent !== host && host.parent.location.origin === location.origin) host = host.parent;
  } catch {
    /* a cross-origin parent: this frame keeps a budget of its own */
  }
  return host;
}

let budget = null; // found (or made) when the first view joins: importing this module touches no window
const ownViews = new Set();

function sharedBudget() {
  if (budget) return budget;
  const host = budgetHost();
  host.__shadingLabGl ??= { limit: GL_CONTEXT_BUDGET, views: [], clock: 0, peak: 0 };
  budget = host.__shadingLabGl;
  // a frame that goes away (an iframe removed or navigated) takes its views out of the budget it shares
  if (host !== window) addEventListener('pagehide', () => ownViews.forEach(leave));
  return budget;
}

function leave(view) {
  ownViews.delete(view);
  const i = budget.views.indexOf(view);
  if (i >= 0) budget.views.splice(i, 1);
  serveWaiting();
}
const holders = () => budget.views.filter((v) => v.holds);

/** Frees a slot if none is free, by taking the one of the view out of sight the longest. False if it cannot. */
function makeRoom() {
  if (holders().length < budget.limit) return true;
  const victim = holders()
    .filter((v) => !v.visible && v.canRelease())
    .sort((a, b) => a.seen - b.seen)[0];
  if (!victim) return false;
  victim.release();
  return true;
}

function take(view) {
  view.holds = true;
  budget.peak = Math.max(budget.peak, holders().length);
}

/** Gives free (or freeable) slots to the views in sight that wait for one, most recently seen first. */
function serveWaiting() {
  const waiting = budget.views.filter((v) => v.waiting && v.visible).sort((a, b) => b.seen - a.seen);
  for (const view of waiting) {
    if (!makeRoom()) return;
    view.waiting = false;
    view.grant();
  }
}

/**
 * Registers a view (visible: whether it is near sight now) and makes room for its context, which the caller
 * creates right after. `view` supplies canRelease(); release(), which gives the context up and sets
 * view.holds = false (the browser stops counting it at once); and grant(), which takes the context back and
 * calls held(). Returns { admitted, ... }: when not admitted, the caller gives its new context up at once
 * (the browser counted it for that moment only) and it waits for a slot.
 */
export function joinGlBudget(view, visible) {
  sharedBudget();
  Object.assign(view, { holds: false, waiting: false, visible, seen: ++budget.clock });
  const admitted = makeRoom();
  budget.views.push(view);
  ownViews.add(view);
  if (admitted) take(view);
  return {
    admitted,
    /** The view's context is back (or coming back): it holds a slot again. */
    held: () => take(view),
    /** The view's context is gone: its slot is free. */
    freed() {
      view.holds = false;
      serveWaiting();
    },
    /** The view scrolled in or out of sight; a view back in sight without a context asks for one. */
    setVisible(visible, wantsContext) {
      view.visible = visible;
      view.seen = ++budget.clock;
      if (visible && wantsContext) {
        view.waiting = true;
        serveWaiting();
      } else if (!visible) {
        view.waiting = false;
        serveWaiting(); // this view may now give its slot to one that waits
      }
    },
    /** True while the view waits for a slot it could not get (more views in sight than the budget). */
    get waiting() {
      return view.waiting;
    },
    leave: () => leave(view),
  };
}

/** For tests and diagnostics: the budget, the slots held now, and the most ever held at once. */
export function glBudgetStatus() {
  const { limit, peak, views } = sharedBudget();
  return { limit, held: holders().length, peak, views: views.length };
}
