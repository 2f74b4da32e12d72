// The visibility explorer's spheres: one per chosen term, with GGX D and F = 1, under one small light; the
// probe reads V, G and V against height-correlated Smith there.
import { createSphereGrid } from '../../core/ui/sphere-grid.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { VISIBILITY_TERMS } from '../../math/brdf.js';
import { REFERENCE, RIM_DEG, rimRatios } from './model.js';
import { describeRim } from './words.js';
import { termDefines, termEntry } from '../../math/catalogue/index.js';
import { sharedUniforms } from '../../math/catalogue/uniforms.js';

/** The terms of a visibility term's sphere: GGX D, F = 1. */
export const cellTerms = (key) => ({ F: 'one', D: 'ggx', V: key });

const uniformsOf = (state) => ({
  uLightDir: lightDirFromAngles(state.lightTheta, 135),
  uExposure: state.exposure,
  ...sharedUniforms({ alphaPair: [state.alpha, state.alpha] }),
});

/** The sphere of the user's V: its own program (custom.js's cell: { own, uniforms }). */
const customCell = (c, state) => ({
  label: 'Yours',
  defines: termDefines(cellTerms(c.key)),
  own: c.cell.own,
  uniforms: { ...c.cell.uniforms, ...uniformsOf(state) },
});

/** The sphere of one term's curve (model.js's visibilityCurves): { label, defines, uniforms, probe }. */
export function sphereCell(c, state) {
  if (c.cell) return customCell(c, state);
  const params = { alpha: state.alpha };
  return {
    label: termEntry('visibility', c.key).short,
    defines: termDefines(cellTerms(c.key)),
    uniforms: uniformsOf(state),
    probe: (a) => {
      const V = VISIBILITY_TERMS[c.key](a, params);
      return [
        ['V', V.toPrecision(4)],
        ['G = V (n·l)(n·v)', (V * Math.max(a.nl, 0) * Math.max(a.nv, 0)).toFixed(4)],
        ['V / V Smith corr.', (V / VISIBILITY_TERMS[REFERENCE](a, params)).toFixed(4)],
      ];
    },
  };
}

export function createVisibilitySpheres(container) {
  const grid = createSphereGrid(container, { label: 'Visibility terms on spheres' });
  const note = document.createElement('p');
  note.className = 'rim-note';
  container.append(note);
  return {
    /** One sphere per curve (the user's once its code compiled in the sphere's program), and where to look. */
    draw(curves, state) {
      grid.setCells(curves.filter((c) => c.cell !== null).map((c) => sphereCell(c, state)));
      note.textContent = describeRim(rimRatios(state), state, RIM_DEG);
    },
    get renderer() {
      return grid.renderer;
    },
    get canvas() {
      return grid.canvas;
    },
    dispose() {
      grid.dispose();
      note.remove();
    },
  };
}
