// brdf-lobe: the microfacet BRDF taken apart, in the spirit of Disney's BRDF Explorer. For a light the user
// drags: the BRDF in the plane of incidence (polar), as a 3-D lobe, over the half/difference angles, and its
// directional albedo; each factor (F, D, G, the denominator) can be switched off, and a second BRDF overlaid.
// A's D, V, F or the whole BRDF can be the user's own GLSL, edited and checked in a panel under the views.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { createSettledTask } from '../../core/framework/render-loop.js';
import { DEG } from '../../math/angles.js';
import { schema } from './schema.js';
import { customSlots, lobeScene } from './model.js';
import { createPolarPlot } from './polar-plot.js';
import { createLobeView } from './lobe-view.js';
import { createHalfDiffPair } from './half-diff-pair.js';
import { createAlbedoPlot } from './albedo-plot.js';
import { createReadout } from './readout.js';
import { createCustomArea } from '../../core/ui/custom-area.js';
import { customPlan } from './custom-tables.js';
import { OPENPBR_KEYS, OPENPBR_LAYERS } from './openpbr-lobe.js';
import { ABOUT, TERMS_USED, TITLE, describeLobe3d, describePolar } from './words.js';

export { schema };

const LIGHT_AND_VIEW = ['lightTheta', 'viewTheta', 'viewPhi']; // the (θh, θd) images do not depend on them
const ALBEDO_KEYS = ['D', 'V', 'F', 'alpha', 'f0', 'compare', 'D2', 'V2', 'alpha2', 'brdf', 'params'].concat(
  ['anisotropy', 'convention'],
  OPENPBR_KEYS,
);
const AZIMUTHS = ['lightPhi', 'viewPhi']; // an anisotropic A's albedo depends on the view's azimuth from t
/** Does the albedo plot change with the keys `changed` (null: all)? An anisotropic A's turns with the azimuths. */
function albedoChanged(changed, s, A) {
  const anisotropic = Boolean(A.aniso) || (Boolean(A.openpbr) && s.anisotropy > 0);
  const keys = [...ALBEDO_KEYS, ...CODE_KEYS, ...(anisotropic ? AZIMUTHS : [])];
  return !changed || changed.some((k) => keys.includes(k));
}
const CODE_KEYS = ['codeD', 'codeV', 'codeF', 'codeBRDF'];
/** A's slots that can be the user's: the state key of each one's code, and its panel's title. */
const CUSTOM_SLOTS = {
  D: { codeKey: 'codeD', title: 'A: your D' },
  V: { codeKey: 'codeV', title: 'A: your V' },
  F: { codeKey: 'codeF', title: 'A: your F' },
  brdf: { codeKey: 'codeBRDF', title: 'A: your whole BRDF' },
};

/**
 * The (θh, θd) images and the albedo plot in `bottom`: draw(s, scene, changed) redraws what `changed` (null: all)
 * touches; a change of the azimuths alone (a drag of φl or Δφ, some 40 000 values of an anisotropic BRDF) is drawn
 * once the drag pauses, the lobes it turns meanwhile.
 */
function createSlowParts(bottom) {
  const images = createHalfDiffPair(bottom);
  let albedo = null; // made at the first draw, from its specs (an albedo curve costs 512 samples an angle)
  let waiting = null; // the last state and scene of a drag of the azimuths not drawn yet
  const now = (s, scene, changed) => {
    if (!changed || changed.some((k) => !LIGHT_AND_VIEW.includes(k))) images.draw(s, scene);
    const specs = scene.B ? [scene.A, scene.B] : [scene.A]; // the scene's: the specs are built once a render
    const turn = s.viewPhi * DEG;
    if (!albedo) albedo = createAlbedoPlot(bottom, specs, turn);
    else if (albedoChanged(changed, s, scene.A)) albedo.draw(specs, turn);
  };
  const later = createSettledTask(() => {
    const { s, scene } = waiting;
    waiting = null;
    now(s, scene, AZIMUTHS);
  });
  return {
    draw(s, scene, changed) {
      if (albedo && changed?.every((k) => AZIMUTHS.includes(k))) {
        waiting = { s, scene };
        later.schedule();
        return;
      }
      const missed = waiting !== null; // a drag of the azimuths not drawn yet: draw everything
      later.cancel();
      waiting = null;
      now(s, scene, missed ? null : changed);
    },
    dispose() {
      later.cancel();
      images.dispose();
      albedo?.dispose();
    },
  };
}

const row = (parent, className) => parent.appendChild(Object.assign(document.createElement('div'), { className }));

export function createBrdfLobe(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'brdf-lobe',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const [top, bottom] = [row(shell.view, 'lobe-row'), row(shell.view, 'lobe-row')];
  const update = (partial) => updateState(partial);
  const polar = createPolarPlot(top, { onDrag: update });
  const lobe3d = createLobeView(row(top, 'lobe-3d'), { onContextChange: () => render(null) });
  const slow = createSlowParts(bottom);
  const readout = createReadout(shell.view);
  const custom = createCustomArea(shell.view, {
    slots: CUSTOM_SLOTS,
    chosen: customSlots,
    planOf: customPlan,
    getRenderer: () => lobe3d.renderer,
    getState: () => shell.state,
    update,
    redraw: () => render(null),
  });

  const drawPolar = (s, scene) => {
    const { a, lobeA, lobeB, ms, max } = scene;
    const halfTheta = a.h ? Math.atan2(a.h[0], a.h[2]) / DEG : null;
    const parts = scene.layers?.parts.map(({ key, lobe }) => ({ lobe, ...OPENPBR_LAYERS[key] }));
    const viewOff = Math.abs(scene.v[1]) > 1e-9; // the view off the plane of incidence: its handle is hollow
    const { lightTheta, viewTheta, lightPhi, viewPhi } = s;
    const angles = { lightTheta, viewTheta, lightPhi, viewPhi, halfTheta, viewOff };
    polar.draw({ lobeA, lobeB, lobeMS: ms.lobe, points: ms.points, parts, max, ...angles });
    shell.describe(describePolar(s, scene), polar.canvas);
  };
  const drawLobe3d = (s, scene) => {
    const { l, v, a, max } = scene;
    const fB = scene.fB ?? scene.layers?.fLayer ?? null; // B, or else one of OpenPBR's layers, as the wire grid
    const directions = { n: [0, 0, 1], l, v, h: a.h, mirror: [-l[0], 0, l[2]] };
    // an anisotropic lobe may peak out of the plane of incidence: scale to its largest value over the hemisphere
    // (its values kept for the mesh, which is made of the same directions)
    const values = scene.A.aniso ? new Map(lobe3d.directions.map((d) => [d, scene.fA(d)])) : null;
    const fA = values ? (d) => values.get(d) ?? scene.fA(d) : scene.fA;
    const top = values ? Math.max(max, ...[...values.values()].filter(Number.isFinite)) : max;
    const phi = s.lightPhi + 180; // the plane's mirror side, opposite the light
    lobe3d.update({ fA, fB, max: top, directions, phi, description: describeLobe3d(s, { ...scene, max: top }) });
  };
  const render = (changed) => {
    const s = shell.state;
    const lookups = custom.lookups(s);
    const scene = lobeScene(s, lookups);
    drawPolar(s, scene);
    drawLobe3d(s, scene);
    slow.draw(s, scene, changed);
    readout.draw(s, scene);
    custom.showPanels(s);
  };
  const updateState = shell.connect({ title: TITLE, onChanged: render, onStateChange });
  render(null);

  return {
    update,
    getState: () => shell.state,
    /** For tests: the 3-D view's lobe A and arrows as drawn, in the patch's frame (lobe-view.js). */
    getLobe3d: () => lobe3d.drawn(),
    dispose() {
      polar.dispose();
      lobe3d.dispose();
      slow.dispose();
      custom.dispose();
      shell.dispose();
    },
  };
}

export const widget = { name: 'brdf-lobe', schema, create: createBrdfLobe, terms: TERMS_USED };
