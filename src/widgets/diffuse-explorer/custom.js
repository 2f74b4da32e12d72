// The diffuse explorer's user-written term (customDiffuse): its f wherever the plots and the table read a model,
// from the GPU (the user's code only runs as GLSL). The inputs are recorded by running the plots' own functions once
// with a recording f, so the user's term is read at exactly the (n·l, n·v, cos φ) the catalogue's terms are; each
// becomes l, v in the local frame (v in the x–z plane, l at azimuth φ), σ in radians as its α.
import { createCustomArea } from '../../core/ui/custom-area.js';
import { createCustomSphere } from '../../core/ui/custom-sphere.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { CUSTOM, lightSweep, paramsOf, profile, tradeOff } from './model.js';
import { cellDefines } from './spheres.js';

const SLOTS = { diffuse: { codeKey: 'codeDiffuse', title: 'Your diffuse term: one more sphere and curve per plot' } };
const keyOf = (nl, nv, cosPhi) => `${nl} ${nv} ${cosPhi}`;

/** Every (n·l, n·v, cos φ) the plots and the table read the user's f at, for the state. */
function readsOf(state) {
  const seen = new Map();
  const record = (nl, nv, cosPhi) => {
    seen.set(keyOf(nl, nv, cosPhi), [nl, nv, cosPhi]);
    return 0;
  };
  const only = { ...state, diffuse: [CUSTOM] };
  profile(only, lightDirFromAngles(state.lightTheta, state.lightPhi), record);
  lightSweep(only, record);
  tradeOff(only, record);
  return [...seen.values()];
}

/** l and v in the local frame for (n·l, n·v, cos φ): v in the x–z plane, l at azimuth φ from it. */
function directions(nl, nv, cosPhi) {
  const [sl, sv] = [Math.sqrt(Math.max(1 - nl * nl, 0)), Math.sqrt(Math.max(1 - nv * nv, 0))];
  const sinPhi = Math.sqrt(Math.max(1 - cosPhi * cosPhi, 0));
  return [sl * cosPhi, sl * sinPhi, nl, sv, 0, nv];
}

function planDiffuse(state) {
  const reads = readsOf(state);
  const { cdiff, sigma } = paramsOf(state);
  const read = (out) => {
    const values = new Map(reads.map((r, i) => [keyOf(...r), Number.isFinite(out[4 * i]) ? out[4 * i] : 0]));
    return (nl, nv, cosPhi) => values.get(keyOf(nl, nv, cosPhi)) ?? 0;
  };
  return {
    key: JSON.stringify([state.cdiff, state.sigma, state.lightTheta, state.lightPhi, state.viewTheta]),
    inputs: reads.map((r) => [cdiff, ...directions(...r), sigma]),
    read,
  };
}

/** `io`: { getRenderer, getState, update, redraw } as createCustomArea's. */
export function createCustomDiffuse(container, io) {
  const area = createCustomArea(container, {
    ...io,
    slots: SLOTS,
    chosen: (s) => (s.diffuse.includes(CUSTOM) ? ['diffuse'] : []),
    planOf: (_, s) => planDiffuse(s),
  });
  const sphere = createCustomSphere(io.getRenderer);
  return {
    /** The user's f(n·l, n·v, cos φ) for the state (read where the plots read it), or null until its code ran. */
    f: (state) => area.lookups(state).diffuse ?? null,
    /** The custom sphere's { own, uniforms }, or null (after f()). */
    cell: (state) => sphere.cell(area, 'diffuse', state, cellDefines(CUSTOM)),
    showPanel: (state) => area.showPanels(state),
    dispose: () => area.dispose(),
  };
}
