// The visibility explorer's user-written V (customV): its G = V (n·l)(n·v) over the plots' angles, from the GPU
// (the user's code only runs as GLSL), and its sphere (GGX D, F = 1, like the others).
import { createCustomArea } from '../../core/ui/custom-area.js';
import { createCustomSphere } from '../../core/ui/custom-sphere.js';
import { termDefines } from '../../math/catalogue/index.js';
import { CUSTOM, cosinesOf } from './model.js';
import { cellTerms } from './spheres.js';

const SLOTS = { V: { codeKey: 'codeV', title: 'Your V: one more curve and sphere' } };

/** What the GPU evaluates for the state: V at the plots' (n·l, n·v), read back as G. */
function planV(state) {
  const cosines = cosinesOf(state);
  const read = (out) =>
    Float64Array.from(cosines, ([nl, nv], i) => (Number.isFinite(out[4 * i]) ? out[4 * i] * nl * nv : 0));
  return {
    key: `${state.alpha} ${state.config} ${state.viewTheta}`,
    inputs: cosines.map((c) => [...c, state.alpha]),
    read,
  };
}

/** `io`: { getRenderer, getState, update, redraw } as createCustomArea's. */
export function createCustomV(container, io) {
  const area = createCustomArea(container, {
    ...io,
    slots: SLOTS,
    chosen: (s) => (s.V.includes(CUSTOM) ? ['V'] : []),
    planOf: (_, s) => planV(s),
  });
  const sphere = createCustomSphere(io.getRenderer);
  return {
    /** The user's G over ANGLES for the state, or null until its code has run. */
    G: (state) => area.lookups(state).V ?? null,
    /** The custom sphere's { own, uniforms }, or null (after G()). */
    cell: (state) => sphere.cell(area, 'V', state, termDefines(cellTerms(CUSTOM))),
    showPanel: (state) => area.showPanels(state),
    dispose: () => area.dispose(),
  };
}
