// @ts-check
// Whether the reader is in the middle of a gesture on a widget: a pointer pressed on it (a drag on its view, a
// slider of its controls), a key held on it (from its first repeat to its release), or a wheel turning over it.
// A view drawn on demand asks this, not how fast its last frames came, whether a frame is one of a drag: a slow
// machine spaces a drag's frames out, but the gesture is still the same one.

const WHEEL_QUIET_MS = 150; // a wheel has no release: its turn ends once its events pause this long

/**
 * Watches gestures that start on `element`'s widget (the element itself outside a widget), looked up as each
 * starts: a view may be made before its widget is in place. `onEnd()` runs when the last one ends. Returns
 * `{ held, dispose() }`; `held` is true while a gesture is under way.
 * @param {HTMLElement} element
 * @param {() => void} onEnd
 */
export function watchHeldInput(element, onEnd) {
  const pointers = new Set();
  const keys = new Set();
  let wheelTimer = 0;
  const held = () => pointers.size > 0 || keys.size > 0 || wheelTimer !== 0;
  const release = (/** @type {() => void} */ change) => {
    const was = held();
    change();
    if (was && !held()) onEnd();
  };

  const on = (/** @type {Event} */ e) =>
    e.target instanceof Node && (element.closest('.widget') ?? element).contains(e.target);
  // a <select>'s list takes the release away from the page: its choice is a lone change
  const down = (/** @type {PointerEvent} */ e) =>
    on(e) && !(e.target instanceof HTMLSelectElement) && pointers.add(e.pointerId);
  const up = (/** @type {PointerEvent} */ e) => release(() => pointers.delete(e.pointerId));
  // a pointer that moves with no button down was released where the page could not see it
  const move = (/** @type {PointerEvent} */ e) => e.buttons === 0 && pointers.has(e.pointerId) && up(e);
  const keydown = (/** @type {KeyboardEvent} */ e) => e.repeat && on(e) && keys.add(e.code);
  const keyup = (/** @type {KeyboardEvent} */ e) => release(() => keys.delete(e.code));
  const wheelEnd = () => release(() => (wheelTimer = 0));
  const wheel = (/** @type {WheelEvent} */ e) => {
    if (!on(e)) return;
    clearTimeout(wheelTimer);
    wheelTimer = window.setTimeout(wheelEnd, WHEEL_QUIET_MS);
  };
  const blur = (/** @type {FocusEvent} */ e) =>
    e.target === window && // the window's own, not an element's (seen here in the capture phase)
    release(() => {
      pointers.clear();
      keys.clear();
    });

  // on the window, in the capture phase: a control that stops an event's propagation still tells this watch, and
  // a release counts wherever it happens (a drag may end outside the widget)
  const listeners = /** @type {[string, (e: any) => void][]} */ ([
    ['pointerdown', down],
    ['keydown', keydown],
    ['wheel', wheel],
    ['pointerup', up],
    ['pointermove', move],
    ['pointercancel', up],
    ['keyup', keyup],
    ['blur', blur], // a release the page never sees (another window took the focus)
  ]);
  for (const [type, fn] of listeners) window.addEventListener(type, fn, { capture: true, passive: true });

  return {
    get held() {
      return held();
    },
    dispose() {
      clearTimeout(wheelTimer);
      for (const [type, fn] of listeners) window.removeEventListener(type, fn, { capture: true });
    },
  };
}
