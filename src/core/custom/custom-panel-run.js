// @ts-check
// Runs a user-written term where a view needs its values, and keeps the last good one drawing: code that does
// not pass the static checks (parse.js) or does not compile leaves the previous values in place, with its
// problems on the user's own lines; code that came with a link waits for the user's click; a lost context keeps
// the values already read back. Every value comes from the GPU (evaluateCustom); nothing runs as JS.
import { parseCustom } from './parse.js';
import { evaluateCustom } from './gpu-eval.js';
import { SLOTS } from './slots.js';
import { isTrusted } from './custom-panel-trust.js';
import { watchContext } from './context-watch.js';

/**
 * Where a view needs a slot's values: `key` names what else they depend on (α, the light…), `inputs` are in the
 * slot's order (slots.js), and `read(out)` turns evaluateCustom's four floats per input into the view's lookup.
 * @typedef {{ key: string, inputs: number[][], read: (out: Float32Array) => any }} Plan
 */
/** @typedef {{ line: number, message: string }} Problem */
/**
 * problems: of the code as given (none when it ran); pending: it waits for the user's click; suspect: it was
 * running when the GPU took the context away, and is not run again unless edited; lost: no live context to run it
 * on (lostMessage: why, when the context watch knows); ran: the code whose values are drawn (null when none yet).
 * @typedef {{ problems: Problem[], pending: boolean, suspect: boolean, lost: boolean, lostMessage: string | null,
 *   ran: string | null }} RunStatus
 */

/**
 * The values of the sliders a code declares: the state's value where it has one (clamped), else the default.
 * @param {{ name: string, min: number, max: number, value: number }[]} declared
 * @param {Record<string, number>} values
 */
export function sliderValues(declared, values = {}) {
  return Object.fromEntries(
    declared.map((p) => [
      p.name,
      Math.min(Math.max(Object.hasOwn(values, p.name) ? values[p.name] : p.value, p.min), p.max),
    ]),
  );
}

/**
 * @param {() => any} getRenderer  the three.js renderer the values are computed with (null without WebGL2)
 * @param {() => void} [onContextChange]  its context was lost or has come back: the status changed, redraw
 */
export function createCustomRunner(getRenderer, onContextChange) {
  /** @type {Record<string, string>} the code of each slot that last compiled and ran */
  const good = {};
  /** @type {Record<string, { id: string, lookup: any, code: string }>} */
  const last = {};
  /** slot and code that were running when the GPU took the context away: not run again unless edited */
  const suspects = new Set();
  /** @type {string | null} */
  let lostMessage = null;
  /** @type {import('./context-watch.js').ContextWatch<string> | null} */
  let watch = null;
  const watched = (/** @type {any} */ renderer) =>
    (watch ??= watchContext(renderer, {
      onLost(message, suspect) {
        lostMessage = message;
        if (suspect) suspects.add(suspect);
        onContextChange?.();
      },
      onRestored() {
        lostMessage = null;
        onContextChange?.();
      },
    }));

  /**
   * The code to try, in order: the given one when it may run and passes the static checks, then the last good.
   * @param {string} slotKey
   * @param {string} code
   * @param {RunStatus} status  told when the code waits for a click, is suspected of a lost context, has problems
   */
  function candidates(slotKey, code, status) {
    const slot = SLOTS[/** @type {keyof typeof SLOTS} */ (slotKey)];
    const list = [];
    if (!isTrusted(code, slot.starter)) status.pending = true;
    else if (suspects.has(`${slotKey}\u0000${code}`)) status.suspect = true;
    else {
      const parsed = parseCustom(slotKey, code);
      if (parsed.ok) list.push({ code, declared: parsed.params });
      else status.problems = parsed.problems;
    }
    const fallback = good[slotKey] ?? slot.starter;
    if (fallback !== code) list.push({ code: fallback, declared: parseCustom(slotKey, fallback).params });
    return list;
  }

  /**
   * Evaluates one candidate, watched: new code is "being tried" until its values are back, so that a context the
   * GPU takes away meanwhile names it. Returns the output, or null when the context is gone.
   * @param {any} renderer
   * @param {string} slotKey
   * @param {string} code
   * @param {Record<string, number>} values
   * @param {Plan} plan
   */
  function evaluate(renderer, slotKey, code, values, plan) {
    const w = watched(renderer);
    w.trying(`${slotKey}\u0000${code}`);
    const out = evaluateCustom(renderer, slotKey, code, values, plan.inputs);
    if (renderer.getContext().isContextLost()) return null; // the watch's event blames this code
    if (out instanceof Float32Array) w.drew();
    else w.trying(/** @type {any} */ (null)); // a refusal is no program: nothing is being tried
    return out;
  }

  /**
   * The lookup of `slotKey` for `plan` with `code` (or the last good code), and why it is what it is.
   * @param {string} slotKey
   * @param {string} code
   * @param {Record<string, number>} params  the state's slider values
   * @param {Plan} plan
   * @returns {{ lookup: any, status: RunStatus }}
   */
  function run(slotKey, code, params, plan) {
    const renderer = getRenderer();
    const lost = !renderer || renderer.getContext().isContextLost();
    /** @type {RunStatus} */
    const status = { problems: [], pending: false, suspect: false, lost, lostMessage, ran: null };
    for (const c of candidates(slotKey, code, status)) {
      const values = sliderValues(c.declared, params);
      const id = `${c.code}\u0000${JSON.stringify(values)}\u0000${plan.key}`;
      if (last[slotKey]?.id === id || status.lost) break;
      const out = evaluate(renderer, slotKey, c.code, values, plan);
      if (out === null) status.lost = true;
      else if (!(out instanceof Float32Array)) {
        if (c.code === code) status.problems = out.errors;
        continue;
      } else {
        good[slotKey] = c.code;
        last[slotKey] = { id, lookup: plan.read(out), code: c.code };
      }
      break;
    }
    return { lookup: last[slotKey]?.lookup ?? null, status: { ...status, ran: last[slotKey]?.code ?? null } };
  }

  return { run, dispose: () => watch?.dispose() };
}
