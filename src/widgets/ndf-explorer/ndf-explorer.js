// ndf-explorer: the talk's five normal distribution functions at one matched width, on linear and log
// axes, their normalisation integrals measured live, and their highlights side by side on spheres.
import { createCurveExplorer } from '../../core/ui/curve-explorer.js';
import { schema } from './schema.js';
import { ndfCurves } from './model.js';
import { createNdfPlots } from './plots.js';
import { createNdfSpheres } from './spheres.js';
import { createNdfTable } from './table.js';
import { ABOUT, TERMS_USED, TITLE, describeSpheres } from './words.js';

export { schema };

const CURVE_KEYS = ['hwhm', 'abcA2', 'sgdP', 'ndfs'];
const LOG_KEYS = [...CURVE_KEYS, 'measured', 'measuredName'];

export function createNdfExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const explorer = createCurveExplorer(container, {
    shell: { name: 'ndf-explorer', schema, initialState, locked, about: ABOUT, terms: TERMS_USED },
    title: TITLE,
    onStateChange,
    curveKeys: CURVE_KEYS,
    curvesOf: ndfCurves,
    views: { plots: createNdfPlots, spheres: createNdfSpheres, table: createNdfTable },
    drawCurves: (plots, curves) => plots.drawLinear(curves),
    afterChange(plots, changed, curves, state) {
      if (changed.some((k) => LOG_KEYS.includes(k))) plots.drawLog(curves, state);
    },
    describeSpheres,
  });
  const { shell, plots } = explorer;

  return {
    update: explorer.update,
    getState: () => shell.state,
    getIntegrals: () => Object.fromEntries(explorer.curves().map((c) => [c.key, c.integral])),
    /** The log plot's measured curve as uPlot holds it: its label and the (θh, value) points drawn. */
    getMeasuredCurve: () => (shell.state.measured.length ? plots.measuredCurve() : null),
    dispose: explorer.dispose,
  };
}

export const widget = { name: 'ndf-explorer', schema, create: createNdfExplorer, terms: TERMS_USED };
