// The WebGL context budget's choices, with stand-in views: who gives a context up, who waits, who is served.
import { beforeAll, describe, expect, it, vi } from 'vitest';

let joinGlBudget;
let glBudgetStatus;
beforeAll(async () => {
  // a top-level window of its own (no parent), as the module expects to find it
  const win = { addEventListener() {} };
  win.parent = win;
  vi.stubGlobal('window', win);
  vi.stubGlobal('location', { origin: 'https://lab.example.org' });
  vi.stubGlobal('addEventListener', () => {});
  ({ joinGlBudget, glBudgetStatus } = await import('../../src/core/gpu/gl-budget.js'));
  window.__shadingLabGl = { limit: 3, views: [], clock: 0, peak: 0 }; // seeded, as a test page can
});

/** A view as gl-context.js makes it: release() frees its slot at once; grant() takes one. */
function makeView(name, visible, log) {
  const view = {
    name,
    live: false,
    canRelease: () => view.live,
    release() {
      view.live = false;
      view.holds = false;
      log.push(`release ${name}`);
    },
    grant() {
      view.live = true;
      slot.held();
      log.push(`grant ${name}`);
    },
  };
  const slot = joinGlBudget(view, visible);
  view.live = slot.admitted;
  return { view, slot };
}

describe('context budget', () => {
  it('admits views up to the limit, then takes the slot of the view out of sight the longest', () => {
    const log = [];
    const a = makeView('a', true, log);
    const b = makeView('b', true, log);
    const c = makeView('c', true, log);
    expect([a, b, c].map((v) => v.slot.admitted)).toEqual([true, true, true]);
    b.slot.setVisible(false, false); // b leaves sight first, then a
    a.slot.setVisible(false, false);
    const d = makeView('d', true, log);
    expect(d.slot.admitted).toBe(true);
    expect(log).toEqual(['release b']);
    expect(glBudgetStatus()).toMatchObject({ limit: 3, held: 3, peak: 3 });

    // every slot held by a view in sight: a newcomer is not admitted and waits
    a.slot.setVisible(true, false);
    const e = makeView('e', true, log);
    expect(e.slot.admitted).toBe(false);
    e.view.live = false;
    e.slot.setVisible(true, true);
    expect(e.slot.waiting).toBe(true);
    expect(log).toEqual(['release b']);

    // one leaves sight: the waiting view gets its slot
    c.slot.setVisible(false, false);
    expect(log).toEqual(['release b', 'release c', 'grant e']);
    expect(e.slot.waiting).toBe(false);

    // b comes back while every slot is held by a view in sight: it waits until d leaves sight
    b.slot.setVisible(true, true);
    expect(b.slot.waiting).toBe(true);
    d.slot.setVisible(false, false);
    expect(log.slice(-2)).toEqual(['release d', 'grant b']);
    expect(glBudgetStatus().held).toBe(3);
    expect(glBudgetStatus().peak).toBe(3);

    // a view that leaves frees its slot for one that waits
    c.slot.setVisible(true, true);
    expect(c.slot.waiting).toBe(true);
    a.view.holds = false;
    a.slot.leave();
    expect(log.at(-1)).toBe('grant c');
    expect(glBudgetStatus()).toMatchObject({ held: 3, views: 4 });
  });
});
