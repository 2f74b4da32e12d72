// The material lab's stretched lobe when its D or V is the user's own GLSL (customDAniso, customVAniso: the
// Anisotropy group's "Stretched D" and "Stretched V"): a panel for each under the images, with the checks every
// user-written D and V has (normalisation over the 2-D hemisphere, Heitz's weak furnace), and the code the lab
// draws with: the code that last ran (the runner vets it: static checks, a compile, the user's click for code from
// a link), compiled once more in the lab's own two programs, where a name of the user's may clash with one of the
// lab's; the last code that compiled there keeps drawing, and the panel says why the new code does not.
import { createCompileGuard } from '../../core/custom/compile-guard.js';
import { SLOTS } from '../../core/custom/slots.js';
import { customTermsFragment } from '../../lab/custom-programs.js';
import { sceneDefines } from '../../lab/lab-defines.js';
import { anisotropyOf, ownSlots } from '../../lab/lab-anisotropy.js';
import { sceneOf } from './model.js';
import { createLabArea } from './custom-brdf.js';

const AREA_SLOTS = {
  DAniso: { codeKey: 'codeDAniso', title: 'Your anisotropic D, stretched on the lab’s sphere' },
  VAniso: { codeKey: 'codeVAniso', title: 'Your anisotropic V, on the lab’s sphere' },
};
// what the runner evaluates: h = l = v = n at one pair, read back only to vet the code (the lab's programs draw it)
const VET = {
  DAniso: { key: '', inputs: [[0, 0, 1, 0.3, 0.1]], read: (out) => out[0] },
  VAniso: { key: '', inputs: [[0, 0, 1, 0, 0, 1, 0.3, 0.1]], read: (out) => out[0] },
};

/** The user's slots `state` draws: those of the stretched lobe, when the model's specular lobe is stretched. */
function chosen(state) {
  const a = anisotropyOf(state);
  return state.brdfSource === 'model' && state.layers !== 'diffuse' && a?.D ? ownSlots(a) : [];
}

/** `io`: { view: () => the lab's view (lab-view.js), getState, update }; `element` holds the panels. */
export function createCustomAnisoTerms(io) {
  const { element, area, getRenderer } = createLabArea(io, { slots: AREA_SLOTS, chosen, planOf: (slot) => VET[slot] });
  const guards = { DAniso: createCompileGuard(getRenderer, { offscreen: true }) };
  guards.VAniso = createCompileGuard(getRenderer, { offscreen: true });

  /** The fragment sources of the lab's two programs (approximation, reference) for the state with `codes`. */
  const sources = (state, codes) => {
    const { scene } = sceneOf(state, null, '', null, null, { code: codes, params: {} });
    return [false, true].map((reference) => customTermsFragment(sceneDefines(scene, reference), codes));
  };

  return {
    element,
    /**
     * The user's terms to draw for `state`: { code: { DAniso?, VAniso? }, params }, or null when it draws none.
     * Until the editor's modules are in, the starters; then the last code of each that ran and compiled in the lab
     * (each tried with the slots after it at their starters, so that one slot's problem is not blamed on another).
     */
    program(state) {
      area.lookups(state);
      const slots = chosen(state);
      /** @type {Record<string, string>} */
      const codes = Object.fromEntries(slots.map((slot) => [slot, SLOTS[slot].starter]));
      for (const slot of slots) {
        const ran = area.ran(slot) ?? SLOTS[slot].starter;
        const { code, problems } = guards[slot].pick(ran, (c) => sources(state, { ...codes, [slot]: c }));
        area.report(slot, problems);
        codes[slot] = code ?? SLOTS[slot].starter;
      }
      area.showPanels(state);
      if (!slots.length) return null;
      const params = Object.assign({}, ...slots.map((slot) => area.sliderValues(slot, codes[slot], state.params)));
      return { code: codes, params };
    },
    dispose: () => area.dispose(),
  };
}
