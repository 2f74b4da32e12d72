// visibility-explorer: every geometry/visibility term of the talk against angle at one roughness, how far
// each is from height-correlated Smith, and what that does to a sphere's edges.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { schema } from './schema.js';
import { visibilityCurves } from './model.js';
import { createVisibilityPlots } from './plots.js';
import { createVisibilitySpheres } from './spheres.js';
import { createVisibilityTable } from './table.js';
import { ABOUT, TERMS_USED, TITLE, describeSpheres } from './words.js';

export { schema };

const CURVE_KEYS = ['alpha', 'config', 'viewTheta', 'terms'];

export function createVisibilityExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'visibility-explorer',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const plotHolder = document.createElement('div');
  shell.view.append(plotHolder);
  let curves = visibilityCurves(shell.state);
  const plots = createVisibilityPlots(plotHolder, curves, shell.state);
  const spheres = createVisibilitySpheres(shell.view);
  const table = createVisibilityTable(shell.view);

  const drawSpheres = () => {
    spheres.draw(curves, shell.state);
    shell.describe(describeSpheres(curves, shell.state), spheres.canvas);
  };
  const onChanged = (changed) => {
    if (changed.some((k) => CURVE_KEYS.includes(k))) {
      curves = visibilityCurves(shell.state);
      plots.draw(curves, shell.state);
      table.draw(curves);
    }
    drawSpheres();
  };
  table.draw(curves);
  drawSpheres();
  const update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    getWorstErrors: () => Object.fromEntries(curves.map((c) => [c.key, c.worst])),
    dispose() {
      plots.dispose();
      spheres.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'visibility-explorer', schema, create: createVisibilityExplorer, terms: TERMS_USED };
