// The material lab's BRDF when it is the user's own GLSL (a whole customBRDF(l, v)): the panel under the images,
// and the code the lab draws with: the code that last ran (the runner vets it: static checks, a compile, the
// user's click for code from a link), compiled once more in the lab's own programs, where a name of the user's may
// clash with one of the lab's; the last code that compiled there keeps drawing.
import { createCustomArea } from '../../core/ui/custom-area.js';
import { createCompileGuard } from '../../core/custom/compile-guard.js';
import { SLOTS } from '../../core/custom/slots.js';
import { customBrdfFragment } from '../../lab/custom-programs.js';
import { sceneDefines } from '../../lab/lab-defines.js';
import { lightsOf } from './model.js';

const AREA_SLOTS = { brdf: { codeKey: 'codeBRDF', title: 'Your whole BRDF f(l, v), rendered in the lab' } };
// what the runner evaluates: f at l = v = n, read back only to vet the code (the lab's programs draw it)
const VET = { key: '', inputs: [[0, 0, 1, 0, 0, 1]], read: (out) => out[0] };

/**
 * A custom area under the lab's images (custom-area.js), drawn with the lab's renderer: `io` { view: () => the lab's
 * view (lab-view.js), getState, update }, `own` { slots, chosen, planOf }. Returns { element, area, getRenderer }.
 */
export function createLabArea({ view, getState, update }, own) {
  const element = document.createElement('div');
  const getRenderer = () => view().viewport?.renderer;
  const area = createCustomArea(element, { getRenderer, getState, update, redraw: () => view().invalidate(), ...own });
  return { element, area, getRenderer };
}

/** `io`: { view: () => the lab's view (lab-view.js), getState, update }; `element` holds the panel. */
export function createCustomBrdf(io) {
  const { element, area, getRenderer } = createLabArea(io, {
    slots: AREA_SLOTS,
    chosen: (s) => (s.brdfSource === 'custom' ? ['brdf'] : []),
    planOf: () => VET,
  });
  const guard = createCompileGuard(getRenderer, { offscreen: true }); // the lab draws into its targets

  /** The fragment sources of the lab's two programs (approximation, reference) for the state, with `code`. */
  const sources = (state) => (code) => {
    const scene = { lights: lightsOf(state), methods: { env: state.envMethod, area: state.areaMethod }, custom: {} };
    return [false, true].map((reference) => customBrdfFragment(sceneDefines(scene, reference), code));
  };

  return {
    element,
    /**
     * The user's BRDF to draw for `state`: { code, params }. Until the editor's modules are in, the starter (its
     * sliders at 0 for that moment); then the last code that ran and compiled in the lab.
     */
    program(state) {
      area.lookups(state);
      const ran = area.ran('brdf') ?? SLOTS.brdf.starter;
      const { code, problems } = guard.pick(ran, sources(state));
      area.report('brdf', problems);
      area.showPanels(state);
      const drawn = code ?? SLOTS.brdf.starter;
      return { code: drawn, params: area.sliderValues('brdf', drawn, state.params) ?? {} };
    },
    dispose: () => area.dispose(),
  };
}
