// @ts-check
// Runs a user-written term where a view needs its values, and keeps the last good one drawing: code that does
// not pass the static checks (parse.js) or does not compile leaves the previous values in place, with its
// problems on the user's own lines; code that came with a link waits for the user's click; a lost context keeps
// the values already read back. Every value comes from the GPU (evaluateCustom); nothing runs as JS.
import { parseCustom } from './parse.js';
import { evaluateCustom } from './gpu-eval.js';
import { SLOTS } from './slots.js';
import { isTrusted } from './custom-panel-trust.js';

/**
 * Where a view needs a slot's values: `key` names what else they depend on (α, the light…), `inputs` are in the
 * slot's order (slots.js), and `read(out)` turns evaluateCustom's four floats per input into the view's lookup.
 * @typedef {{ key: string, inputs: number[][], read: (out: Float32Array) => any }} Plan
 */
/** @typedef {{ line: number, message: string }} Problem */
/**
 * problems: of the code as given (none when it ran); pending: it waits for the user's click; lost: no live
 * context to run it on; ran: the code whose values are drawn (null when none ran yet).
 * @typedef {{ problems: Problem[], pending: boolean, lost: boolean, ran: string | null }} RunStatus
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

/** @param {() => any} getRenderer  the three.js renderer the values are computed with (null without WebGL2) */
export function createCustomRunner(getRenderer) {
  /** @type {Record<string, string>} the code of each slot that last compiled and ran */
  const good = {};
  /** @type {Record<string, { id: string, lookup: any, code: string }>} */
  const last = {};

  /**
   * The code to try, in order: the given one when it may run and passes the static checks, then the last good.
   * @param {string} slotKey
   * @param {string} code
   * @param {RunStatus} status  told when the code waits for a click or has problems
   */
  function candidates(slotKey, code, status) {
    const slot = SLOTS[/** @type {keyof typeof SLOTS} */ (slotKey)];
    const list = [];
    if (!isTrusted(code, slot.starter)) status.pending = true;
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
    const status = { problems: [], pending: false, lost, ran: null };
    for (const c of candidates(slotKey, code, status)) {
      const values = sliderValues(c.declared, params);
      const id = `${c.code}\u0000${JSON.stringify(values)}\u0000${plan.key}`;
      if (last[slotKey]?.id === id) break;
      if (lost) break;
      const out = evaluateCustom(renderer, slotKey, c.code, values, plan.inputs);
      if (!(out instanceof Float32Array)) {
        if (c.code === code) status.problems = out.errors;
        continue;
      }
      good[slotKey] = c.code;
      last[slotKey] = { id, lookup: plan.read(out), code: c.code };
      break;
    }
    return { lookup: last[slotKey]?.lookup ?? null, status: { ...status, ran: last[slotKey]?.code ?? null } };
  }

  return { run };
}
