// A widget's user-written terms: for each slot chosen, a panel with its code, sliders and checks, and the values
// the widget's views need, read back from the GPU (the runner keeps the last good code drawing). The panel's module
// (with CodeMirror and the GLSL parser) is loaded only when a custom term is first chosen; until then nothing of the
// custom term is drawn. A lost GPU context is watched by the runner, which then asks the widget to redraw.
import { whileLoading } from '../framework/debug-hooks.js';

/**
 * The panel's modules (CodeMirror, the GLSL parser, the runner), loaded once: `then(modules)`, or a message in `box`.
 * @param {HTMLElement} box
 * @param {(modules: any[]) => void} then
 */
function loadModules(box, then) {
  const modules = [import('./custom-panel.js'), import('../custom/parse.js'), import('../custom/custom-panel-run.js')];
  return whileLoading(Promise.all(modules)).then(then, () => {
    box.textContent = 'The code editor could not be loaded (offline?). Reload the page to try again.';
  });
}

/**
 * @param {HTMLElement} container
 * @param {object} io
 * @param {Record<string, { codeKey: string, title: string }>} io.slots  each slot the widget offers: the state key
 *   of its code and the panel's title
 * @param {(state: any) => string[]} io.chosen  the slots the state draws as custom
 * @param {(slotKey: string, state: any) => import('../custom/custom-panel-run.js').Plan} io.planOf  what to evaluate
 * @param {() => any} io.getRenderer
 * @param {() => any} io.getState
 * @param {(partial: object) => void} io.update
 * @param {() => void} io.redraw  draws the widget again (the panel's module arrived, or the user clicked Run)
 */
export function createCustomArea(container, { slots, chosen, planOf, getRenderer, getState, update, redraw }) {
  const box = document.createElement('div');
  box.className = 'custom-area';
  container.append(box);
  /** @type {{ panel: any, parse: any, run: any, runner: any } | null} the panel's modules, once loaded */
  let mods = null;
  let loading = null;
  let shownKey = '';
  /** @type {Record<string, any>} */
  const panels = {};
  /** @type {Record<string, import('../custom/custom-panel-run.js').RunStatus>} */
  let statuses = {};

  const load = () =>
    (loading ??= loadModules(box, ([panel, parse, run]) => {
      mods = { panel, parse, run, runner: run.createCustomRunner(getRenderer, redraw) };
      redraw();
    }));

  /** @param {string} slotKey */
  const createPanel = (slotKey) =>
    mods?.panel.createCustomPanel(box, {
      slotKey,
      code: getState()[slots[slotKey].codeKey],
      title: slots[slotKey].title,
      getRenderer,
      onCode: (/** @type {string} */ code) => update({ [slots[slotKey].codeKey]: code }),
      onParam: (/** @type {string} */ name, /** @type {number} */ value) =>
        update({ params: { ...getState().params, [name]: value } }),
      onRun: redraw,
    });

  return {
    /**
     * The lookups of the state's custom slots, each present once its code (or the starter) has run.
     * @returns {Record<string, any>}
     */
    lookups(state) {
      statuses = {};
      const keys = chosen(state);
      if (!keys.length) return {};
      if (!mods) {
        load();
        return {};
      }
      /** @type {Record<string, any>} */
      const out = {};
      for (const k of keys) {
        const { lookup, status } = mods.runner.run(k, state[slots[k].codeKey], state.params, planOf(k, state));
        if (lookup) out[k] = lookup;
        statuses[k] = status;
      }
      return out;
    },
    /** The code whose values are drawn for `slotKey` (after lookups()), or null. @param {string} slotKey */
    ran: (slotKey) => statuses[slotKey]?.ran ?? null,
    /**
     * Problems a widget met with the code that ran (its own program did not compile): shown with the others.
     * @param {string} slotKey
     * @param {{ line: number, message: string }[]} problems
     */
    report(slotKey, problems) {
      const s = statuses[slotKey];
      if (s && problems.length) statuses[slotKey] = { ...s, problems: [...s.problems, ...problems] };
    },
    /**
     * The values of the sliders `code` declares (the state's `params`, clamped; else each default), or null before
     * the parser is loaded.
     * @param {string} slotKey
     * @param {string} code
     * @param {Record<string, number>} params
     */
    sliderValues(slotKey, code, params) {
      if (!mods) return null;
      return mods.run.sliderValues(mods.parse.parseCustom(slotKey, code).params, params); // parsed once per code
    },
    /** The panels of the chosen slots, each told how its code ran (after lookups()); unchanged ones are left. */
    showPanels(state) {
      const codes = Object.keys(statuses).map((k) => state[slots[k].codeKey]);
      const key = JSON.stringify([statuses, codes, state.params, Boolean(mods)]);
      if (key === shownKey) return;
      shownKey = key;
      for (const k of Object.keys(panels)) {
        if (statuses[k]) continue;
        panels[k].dispose();
        delete panels[k];
      }
      for (const [k, status] of Object.entries(statuses)) {
        panels[k] ??= createPanel(k);
        panels[k].show({ code: state[slots[k].codeKey], params: state.params, status });
      }
    },
    dispose() {
      mods?.runner.dispose();
      Object.values(panels).forEach((p) => p.dispose());
      box.remove();
    },
  };
}
