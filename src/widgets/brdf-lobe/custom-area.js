// BRDF A's user-written terms: for each slot chosen (D, V, F, or the whole BRDF) a panel with its code, sliders
// and checks, and the lookups the views draw, read back from the GPU. The panel's module (with CodeMirror and the
// GLSL parser) is loaded only when a custom term is first chosen; until then A draws the starter's term.
import { customPlan } from './custom-tables.js';
import { customSlots } from './model.js';

const CODE_KEY = { D: 'codeD', V: 'codeV', F: 'codeF', brdf: 'codeBRDF' };
const TITLES = { D: 'A: your D', V: 'A: your V', F: 'A: your F', brdf: 'A: your whole BRDF' };

/**
 * @param {HTMLElement} container
 * @param {{ getRenderer: () => any, getState: () => any, update: (partial: object) => void, redraw: () => void }} io
 */
export function createCustomArea(container, { getRenderer, getState, update, redraw }) {
  const box = document.createElement('div');
  box.className = 'custom-area';
  container.append(box);
  let panelModule = null;
  let loading = null;
  let runner = null;
  const panels = {};
  let statuses = {};

  function load() {
    loading ??= import('../../core/ui/custom-panel.js').then(
      (m) => {
        panelModule = m;
        runner = m.createCustomRunner(getRenderer, redraw);
        redraw();
      },
      () => {
        box.textContent = 'The code editor could not be loaded (offline?). Reload the page to try again.';
      },
    );
  }

  function createPanel(slotKey) {
    const codeKey = CODE_KEY[slotKey];
    return panelModule.createCustomPanel(box, {
      slotKey,
      code: getState()[codeKey],
      title: TITLES[slotKey],
      getRenderer,
      onCode: (code) => update({ [codeKey]: code }),
      onParam: (name, value) => update({ params: { ...getState().params, [name]: value } }),
      onRun: redraw,
    });
  }

  return {
    /** A's lookups for the state: { D, V, F, brdf }, each present once its code (or the starter) has run. */
    lookups(state) {
      statuses = {};
      const slots = customSlots(state);
      if (!slots.length) return {};
      if (!runner) {
        load();
        return {};
      }
      const out = {};
      for (const k of slots) {
        const { lookup, status } = runner.run(k, state[CODE_KEY[k]], state.params, customPlan(k, state));
        if (lookup) out[k] = lookup;
        statuses[k] = status;
      }
      return out;
    },
    /** The panels of the chosen slots, each told how its code ran (after lookups()). */
    showPanels(state) {
      for (const k of Object.keys(panels)) {
        if (statuses[k]) continue;
        panels[k].dispose();
        delete panels[k];
      }
      for (const [k, status] of Object.entries(statuses)) {
        panels[k] ??= createPanel(k);
        panels[k].show({ code: state[CODE_KEY[k]], params: state.params, status });
      }
    },
    dispose() {
      runner?.dispose();
      Object.values(panels).forEach((p) => p.dispose());
      box.remove();
    },
  };
}
