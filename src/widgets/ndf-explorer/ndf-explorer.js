// ndf-explorer: the talk's five normal distribution functions at one matched width, on linear and log
// axes, their normalisation integrals measured live, and their highlights side by side on spheres; and a sixth,
// the user's own D in GLSL, edited in a panel under the table.
import { createCurveExplorer } from '../../core/ui/curve-explorer.js';
import { schema } from './schema.js';
import { ndfCurves, withStyle } from './model.js';
import { createCustomD } from './custom.js';
import { createNdfPlots } from './plots.js';
import { createNdfSpheres } from './spheres.js';
import { createNdfTable } from './table.js';
import { ABOUT, TERMS_USED, TITLE, describeSpheres } from './words.js';

export { schema };

const CURVE_KEYS = ['hwhm', 'abcA2', 'sgdP', 'D', 'codeD', 'params', 'anisotropy', 'convention'];
const LOG_KEYS = [...CURVE_KEYS, 'measured', 'measuredName'];

export function createNdfExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  let explorer = null; // made below: the custom D's hooks run only once it is
  const editorHolder = document.createElement('div');
  const customD = createCustomD(editorHolder, {
    getRenderer: () => explorer?.spheres.renderer,
    getState: () => explorer.shell.state,
    update: (partial) => explorer.update(partial),
    redraw: () => explorer.refresh(),
  });
  /** The five NDFs' curves, then the user's once its code ran. */
  const curvesOf = (state) => {
    const own = customD.curve(state);
    return own ? [...ndfCurves(state), { ...own, ...withStyle(own.key) }] : ndfCurves(state);
  };
  explorer = createCurveExplorer(container, {
    shell: { name: 'ndf-explorer', schema, initialState, locked, about: ABOUT, terms: TERMS_USED },
    title: TITLE,
    onStateChange,
    curveKeys: CURVE_KEYS,
    curvesOf,
    views: { plots: createNdfPlots, spheres: createNdfSpheres, table: createNdfTable },
    drawCurves: (plots, curves, state) => {
      plots.drawLinear(curves);
      plots.drawMaps(curves, state);
    },
    afterChange(plots, changed, curves, state) {
      if (changed.some((k) => LOG_KEYS.includes(k))) plots.drawLog(curves, state);
      customD.showPanel(state);
    },
    describeSpheres,
  });
  const { shell, plots } = explorer;
  shell.view.append(editorHolder);
  customD.showPanel(shell.state);

  return {
    update: explorer.update,
    getState: () => shell.state,
    getIntegrals: () => Object.fromEntries(explorer.curves().map((c) => [c.key, c.integral])),
    /** Each curve drawn on the linear plot: key → D at ANGLES (model.js), in 1/sr. */
    getCurves: () => Object.fromEntries(explorer.curves().map((c) => [c.key, Array.from(c.values)])),
    /** The log plot's measured curve as uPlot holds it: its label and the (θh, value) points drawn. */
    getMeasuredCurve: () => (shell.state.measured.length ? plots.measuredCurve() : null),
    dispose() {
      customD.dispose();
      explorer.dispose();
    },
  };
}

export const widget = { name: 'ndf-explorer', schema, create: createNdfExplorer, terms: TERMS_USED };
