// ndf-explorer: the talk's five normal distribution functions at one matched width, on linear and log
// axes, their normalisation integrals measured live, and their highlights side by side on spheres.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
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
  const shell = createWidgetShell(container, {
    name: 'ndf-explorer',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const plotHolder = document.createElement('div');
  shell.view.append(plotHolder);
  let curves = ndfCurves(shell.state);
  const plots = createNdfPlots(plotHolder, curves, shell.state);
  const spheres = createNdfSpheres(shell.view);
  const table = createNdfTable(shell.view);

  const drawSpheres = () => {
    spheres.draw(curves, shell.state);
    shell.describe(describeSpheres(curves, shell.state), spheres.canvas);
  };
  const onChanged = (changed) => {
    if (changed.some((k) => CURVE_KEYS.includes(k))) {
      curves = ndfCurves(shell.state);
      plots.drawLinear(curves);
      table.draw(curves);
    }
    if (changed.some((k) => LOG_KEYS.includes(k))) plots.drawLog(curves, shell.state);
    drawSpheres();
  };
  table.draw(curves);
  drawSpheres();
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getIntegrals: () => Object.fromEntries(curves.map((c) => [c.key, c.integral])),
    /** The log plot's measured curve as uPlot holds it: its label and the (θh, value) points drawn. */
    getMeasuredCurve: () => (shell.state.measured.length ? plots.measuredCurve() : null),
    dispose() {
      plots.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'ndf-explorer', schema, create: createNdfExplorer, terms: TERMS_USED };
