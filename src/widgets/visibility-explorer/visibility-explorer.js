// visibility-explorer: every geometry/visibility term of the talk against angle at one roughness, how far
// each is from height-correlated Smith, and what that does to a sphere's edges.
import { createCurveExplorer } from '../../core/ui/curve-explorer.js';
import { schema } from './schema.js';
import { visibilityCurves } from './model.js';
import { createVisibilityPlots } from './plots.js';
import { createVisibilitySpheres } from './spheres.js';
import { createVisibilityTable } from './table.js';
import { ABOUT, TERMS_USED, TITLE, describeSpheres } from './words.js';

export { schema };

const CURVE_KEYS = ['alpha', 'config', 'viewTheta', 'terms'];

export function createVisibilityExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const explorer = createCurveExplorer(container, {
    shell: { name: 'visibility-explorer', schema, initialState, locked, about: ABOUT, terms: TERMS_USED },
    title: TITLE,
    onStateChange,
    curveKeys: CURVE_KEYS,
    curvesOf: visibilityCurves,
    views: { plots: createVisibilityPlots, spheres: createVisibilitySpheres, table: createVisibilityTable },
    drawCurves: (plots, curves, state) => plots.draw(curves, state),
    describeSpheres,
  });

  return {
    update: explorer.update,
    getState: () => explorer.shell.state,
    getWorstErrors: () => Object.fromEntries(explorer.curves().map((c) => [c.key, c.worst])),
    dispose: explorer.dispose,
  };
}

export const widget = { name: 'visibility-explorer', schema, create: createVisibilityExplorer, terms: TERMS_USED };
