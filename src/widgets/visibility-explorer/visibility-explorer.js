// visibility-explorer: every geometry/visibility term of the talk against angle at one roughness, how far
// each is from height-correlated Smith, and what that does to a sphere's edges; and the user's own V in GLSL,
// edited in a panel under the table.
import { createCurveExplorer } from '../../core/ui/curve-explorer.js';
import { schema } from './schema.js';
import { CUSTOM, visibilityCurves } from './model.js';
import { createCustomV } from './custom.js';
import { createVisibilityPlots } from './plots.js';
import { createVisibilitySpheres } from './spheres.js';
import { createVisibilityTable } from './table.js';
import { ABOUT, TERMS_USED, TITLE, describeSpheres } from './words.js';

export { schema };

const CURVE_KEYS = ['alpha', 'config', 'viewTheta', 'V', 'codeV', 'params', 'anisotropy', 'convention'];

export function createVisibilityExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  let explorer = null; // made below: the custom V's hooks run only once it is
  const editorHolder = document.createElement('div');
  const customV = createCustomV(editorHolder, {
    getRenderer: () => explorer?.spheres.renderer,
    getState: () => explorer.shell.state,
    update: (partial) => explorer.update(partial),
    redraw: () => explorer.refresh(),
  });
  /** The catalogue's terms' curves, and the user's once its code ran (with its sphere's program). */
  const curvesOf = (state) => {
    const curves = visibilityCurves(state, customV.G(state));
    const own = curves.find((c) => c.key === CUSTOM);
    if (own) own.cell = customV.cell(state);
    return curves;
  };
  explorer = createCurveExplorer(container, {
    shell: { name: 'visibility-explorer', schema, initialState, locked, about: ABOUT, terms: TERMS_USED },
    title: TITLE,
    onStateChange,
    curveKeys: CURVE_KEYS,
    curvesOf,
    views: { plots: createVisibilityPlots, spheres: createVisibilitySpheres, table: createVisibilityTable },
    drawCurves: (plots, curves, state) => plots.draw(curves, state),
    afterChange: (plots, changed, curves, state) => customV.showPanel(state),
    describeSpheres,
  });
  explorer.shell.view.append(editorHolder);
  customV.showPanel(explorer.shell.state);

  return {
    update: explorer.update,
    getState: () => explorer.shell.state,
    getWorstErrors: () => Object.fromEntries(explorer.curves().map((c) => [c.key, c.worst])),
    /** Each curve's G over ANGLES (model.js), as the G plot draws it. */
    getCurves: () => Object.fromEntries(explorer.curves().map((c) => [c.key, Array.from(c.G)])),
    /** The azimuth plot's curves: label → G1 over 0°–180° (azimuth.js). */
    getAzimuthCurves: () => explorer.plots.azimuthCurves(),
    dispose() {
      customV.dispose();
      explorer.dispose();
    },
  };
}

export const widget = { name: 'visibility-explorer', schema, create: createVisibilityExplorer, terms: TERMS_USED };
