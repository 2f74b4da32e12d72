// The NDF explorer's sixth curve and sphere: the user's own D (customD), at the GGX α of the matched width (so the
// starter, GGX, lies on GGX's curve). Its values and its normalisation integral come from the GPU (the user's code
// only runs as GLSL): D over the plots' angles and over the nodes of the integral the table uses for the others
// (ndfProjectedIntegral: Simpson in θ = π s²/2, 4000 intervals).
import { createCustomArea } from '../../core/ui/custom-area.js';
import { createCustomSphere } from '../../core/ui/custom-sphere.js';
import { matchNdfWidths } from '../../math/ndf-width.js';
import { ndfProjectedIntegral } from '../../math/integrate.js';
import { DEG } from '../../math/angles.js';
import { termDefines } from '../../math/catalogue/index.js';
import { ANGLES } from './model.js';
import { cellTerms } from './spheres.js';

export const CUSTOM = 'custom';
const SLOTS = { D: { codeKey: 'codeD', title: 'Your D: the sixth curve and sphere (at GGX’s α for this width)' } };

/** The cosines ndfProjectedIntegral reads D at, in its order (recorded from a call). */
const INTEGRAL_COSINES = (() => {
  const cosines = [];
  ndfProjectedIntegral((c) => (cosines.push(c), 0));
  return cosines;
})();
const PLOT_COSINES = Array.from(ANGLES, (deg) => Math.cos(deg * DEG));

/** The GGX α of the state's matched width: the α the user's D is given. */
export const customAlpha = (state) => matchNdfWidths(state.hwhm, { abcA2: state.abcA2, sgdP: state.sgdP }).ggx.alpha;

/** What the GPU evaluates for the state: D at the plots' angles, then at the integral's nodes. */
function planD(state) {
  const alpha = customAlpha(state);
  const inputs = [...PLOT_COSINES, ...INTEGRAL_COSINES].map((c) => [c, alpha]);
  const read = (out) => {
    const at = (i) => (Number.isFinite(out[4 * i]) ? out[4 * i] : 0); // NaN, Inf: 0 here, counted by the checks
    const values = Float64Array.from(PLOT_COSINES, (_, i) => at(i));
    const byCosine = new Map(INTEGRAL_COSINES.map((c, i) => [c, at(PLOT_COSINES.length + i)]));
    return { alpha, values, integral: ndfProjectedIntegral((c) => byCosine.get(c)) };
  };
  return { key: `${alpha}`, inputs, read };
}

/** `io`: { getRenderer, getState, update, redraw } as createCustomArea's. */
export function createCustomD(container, io) {
  const area = createCustomArea(container, {
    ...io,
    slots: SLOTS,
    chosen: (s) => (s.D.includes(CUSTOM) ? ['D'] : []),
    planOf: (_, s) => planD(s),
  });
  const sphere = createCustomSphere(io.getRenderer);
  return {
    /** The custom curve of the state ({ key, p, values, integral, sphere }), or null until its code has run. */
    curve(state) {
      const lookup = area.lookups(state).D;
      if (!lookup) return null;
      const cell = sphere.cell(area, 'D', state, termDefines(cellTerms(CUSTOM)));
      return { key: CUSTOM, p: { alpha: lookup.alpha }, values: lookup.values, integral: lookup.integral, cell };
    },
    showPanel: (state) => area.showPanels(state),
    dispose: () => area.dispose(),
  };
}
