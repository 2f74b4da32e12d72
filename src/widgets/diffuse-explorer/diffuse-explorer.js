// diffuse-explorer: Lambert, the diffuse-specular trade-off (Fresnel-weighted Lambert, Ashikhmin-Shirley) and
// Oren-Nayar (full and qualitative), on a row of GPU-shaded spheres under a light the user moves, and as plots:
// the brightness across a sphere (the rough "full moon" flattening), radiance as the light sweeps past a fixed
// view, and the light returned by specular plus diffuse against the view angle. One more model may be the user's
// own GLSL, edited in a panel under the plots.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { schema } from './schema.js';
import { lightSweep, profile, tradeOff } from './model.js';
import { createDiffuseSpheres } from './spheres.js';
import { createLightPad } from './light-pad.js';
import { createProfilePlot, createSweepPlot, createTradeOffPlot } from './plots.js';
import { createFlatnessTable } from './table.js';
import { ABOUT, TERMS_USED, TITLE, describeSpheres } from './words.js';
import { createCustomDiffuse } from './custom.js';

export { schema };

const LIGHT_KEYS = ['lightTheta', 'lightPhi'];
const MODEL_KEYS = ['diffuse', 'sigma', 'cdiff', 'f0', 'codeDiffuse', 'params'];

export function createDiffuseExplorer(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'diffuse-explorer',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const lightDir = () => lightDirFromAngles(shell.state.lightTheta, shell.state.lightPhi);
  let update = () => {};
  const editorHolder = document.createElement('div');
  const custom = createCustomDiffuse(editorHolder, {
    getRenderer: () => spheres.renderer,
    getState: () => shell.state,
    update: (partial) => update(partial),
    redraw: () => onChanged([...MODEL_KEYS, ...LIGHT_KEYS, 'viewTheta']),
  });
  let ownF = custom.f(shell.state); // the user's f, read back from the GPU (null until it ran)
  // the spheres, their probe readout and, beside it, the pad that moves their light
  const stage = shell.view.appendChild(Object.assign(document.createElement('div'), { className: 'diffuse-stage' }));
  const spheres = createDiffuseSpheres(stage);
  const pad = createLightPad(stage, {
    label: 'Light direction for the spheres and the profile plot',
    get: () => shell.state,
    set: (partial) => update(partial),
  });
  const plotHolder = shell.view.appendChild(document.createElement('div'));
  let profileData = profile(shell.state, lightDir(), ownF);
  const profilePlot = createProfilePlot(plotHolder, shell.state, profileData);
  const table = createFlatnessTable(plotHolder);
  const sweepPlot = createSweepPlot(plotHolder, shell.state, lightSweep(shell.state, ownF));
  const tradePlot = createTradeOffPlot(plotHolder, shell.state, tradeOff(shell.state, ownF));
  shell.view.append(editorHolder);

  const drawSpheres = () => {
    spheres.draw(shell.state, lightDir(), ownF ? custom.cell(shell.state) : null);
    custom.showPanel(shell.state);
    shell.describe(describeSpheres(shell.state), spheres.canvas);
  };
  const onChanged = (changed) => {
    const touches = (...keys) => changed.some((k) => keys.includes(k));
    const s = shell.state;
    if (touches(...MODEL_KEYS, ...LIGHT_KEYS, 'viewTheta')) ownF = custom.f(s); // the user's f is read at all three
    if (touches(...MODEL_KEYS, ...LIGHT_KEYS)) {
      profileData = profile(s, lightDir(), ownF);
      profilePlot.draw(s, profileData);
      table.draw(s, profileData);
    }
    if (touches(...MODEL_KEYS, 'viewTheta')) sweepPlot.draw(s, lightSweep(s, ownF));
    if (touches(...MODEL_KEYS)) tradePlot.draw(s, tradeOff(s, ownF));
    if (touches(...LIGHT_KEYS)) pad.draw();
    drawSpheres();
  };
  table.draw(shell.state, profileData);
  drawSpheres();
  update = shell.connect({ title: TITLE, onChanged, onStateChange });

  return {
    update,
    getState: () => shell.state,
    /** The data each plot draws, [xs, ...series], as uPlot holds it. */
    getPlots: () => ({ profile: profilePlot.plotted(), sweep: sweepPlot.plotted(), tradeOff: tradePlot.plotted() }),
    dispose() {
      pad.dispose();
      profilePlot.dispose();
      sweepPlot.dispose();
      tradePlot.dispose();
      spheres.dispose();
      custom.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'diffuse-explorer', schema, create: createDiffuseExplorer, terms: TERMS_USED };
