// material-lab: the playground of the talk's last part. A sphere with a material from the F0 tables (or your
// own), the BRDF's terms to choose, and four kinds of light to switch on: punctual, a sphere (area) light, an
// environment, ambient. Each light is rendered by the approximation chosen for it; beside it the same view by
// a converging Monte Carlo reference, the error image, and the RMS error and GPU time of the approximation. The BRDF
// may be a measured table or the user's own GLSL, edited in a panel under the images.
import { createWidgetShell } from '../../core/framework/widget-shell.js';
import { MAX_FILE_BYTES, parseEnvironmentFile } from '../../lab/environment-files.js';
import { createLabView } from '../../lab/lab-view.js';
import { createNotesList } from '../../lab/lab-approximations.js';
import { attachEnvironmentDrop } from './environment-drop.js';
import { createMeasuredMaterial } from './measured-material.js';
import { createLabFrame } from './lab-frame.js';
import { createCustomBrdf } from './custom-brdf.js';
import { createCustomAnisoTerms } from './custom-aniso.js';
import { createOpenPbrPanel } from './openpbr-panel.js';
import { BRUSHED_ALUMINIUM, WHITE_LAMBERT_HEAD_ON, missingFile } from './model.js';
import { schema } from './schema.js';
import { createReadout } from './views.js';
import { ABOUT, NOTICES, TERMS_USED, captions, description, readoutHtml } from './words.js';
import { sampleTarget } from '../../core/framework/debug-hooks.js';

export { schema };

export function createMaterialLab(container, initialState = {}, { onStateChange, locked } = {}) {
  const shell = createWidgetShell(container, {
    name: 'material-lab',
    schema,
    initialState,
    locked,
    about: ABOUT,
    terms: TERMS_USED,
  });
  const readout = createReadout(startingPoints((p) => update(p)));
  const notes = createNotesList(); // under the images: how each light's approximation treats the chosen terms
  const file = { key: '', pixels: null }; // a new key for every file taken: a second file of the same name is used too
  const measured = createMeasuredMaterial({
    onChange: () => (shell.state.brdfSource === 'measured' ? view.invalidate() : update({ brdfSource: 'measured' })),
    onError: (message) => shell.notices.show(message),
  });
  const show = (st, lights, scene, stats) => {
    readout.show(readoutHtml(st, stats, lights, view.resolution));
    const table = st.brdfSource === 'measured' ? measured.current : null;
    shell.describe(description(st, lights, stats, table?.name), view.canvas);
    notes.show(scene);
    return captions(st, lights, stats);
  };
  const [ownBrdf, ownTerms] = ownCode({ view: () => view, getState: () => shell.state, update: (p) => update(p) });
  // a gesture held on the widget: OpenPBR's reference (lab-frame.js) and bars wait for its end
  const openpbr = createOpenPbrPanel({ shell, update: (p) => update(p), onRelease: () => view.invalidate() });
  const sources = { state: () => shell.state, measured: () => measured.current, file: () => file };
  const own = { custom: ownBrdf.program, terms: ownTerms.program };
  const lab = createLabFrame({ ...sources, ...own, openpbr: openpbr.material, held: openpbr.held, show });
  const onReset = () => (lab.reset(), measured.reupload());
  const view = createLabView(shell.view, { label: 'Material lab', resolution: 192, frame: lab.frame, onReset });
  view.setPanels(3);
  shell.view.append(readout.element, notes.element, openpbr.element, ownBrdf.element, ownTerms.element); // panels

  const onChanged = (changed) => {
    const has = { measured: Boolean(measured.current), file: Boolean(file.pixels) };
    const missing = missingFile(changed, shell.state, has);
    if (missing) {
      shell.notices.show(NOTICES[missing.notice]);
      update(missing.instead);
    } else view.setDisplay({ exposure: shell.state.exposure, errorScale: shell.state.errorScale });
    openpbr.refresh(shell.state); // the bars follow the state, drawn or not (the view draws only when seen)
  };
  const update = shell.connect({ title: 'Material lab', onChanged, onStateChange });
  onChanged(['environment', 'brdfSource']);
  const useEnvironment = (name, pixels) => {
    file.pixels = pixels;
    file.key = `file:${name}:${performance.now()}`;
    update({ env: true, environment: 'file' });
    view.invalidate();
  };
  const drop = attachEnvironmentDrop(shell.root, {
    maxBytes: MAX_FILE_BYTES,
    accept: '.hdr,.exr,.binary,.mtlx',
    text: NOTICES.dropText,
    onFile: (name, buffer) => takeFile(name, buffer, { measured, useEnvironment, openpbr, notices: shell.notices }),
  });

  return {
    update,
    getState: () => shell.state,
    getStats: () => lab.stats,
    /** The measured table in use ({ name, fit }: fit null until the GGX fit is in), or null. */
    getMeasured: () => (measured.current ? { name: measured.current.name, fit: measured.current.fit } : null),
    getProgress: () => ({ frame: lab.stats?.samples ?? 0, target: sampleTarget(Number(shell.state.refSamples)) }),
    /** Renders the approximation `runs` times and keeps the median time (stats.timingRuns says when it is done). */
    remeasure(runs) {
      lab.remeasure(runs);
      view.invalidate();
    },
    read: (which) => view.lab?.read(which),
    openpbr: openpbr.api(),
    get canvas() {
      return view.canvas;
    },
    get resolution() {
      return view.resolution;
    },
    dispose() {
      [drop, measured, ownBrdf, ownTerms, openpbr, view, shell].forEach((x) => x.dispose());
    },
  };
}

/** The panels of the user's code under the images: the whole BRDF's, and the stretched lobe's D and V. */
const ownCode = (io) => [createCustomBrdf(io), createCustomAnisoTerms(io)];

/** The readout's buttons: the lab's starting points, each a state to take. */
const startingPoints = (update) => [
  { text: NOTICES.headOn, className: 'lab-head-on', onClick: () => update(WHITE_LAMBERT_HEAD_ON) },
  { text: NOTICES.brushed, className: 'lab-brushed', onClick: () => update(BRUSHED_ALUMINIUM) },
];

/**
 * A dropped or picked file: a MERL .binary becomes the measured material, a MaterialX .mtlx the OpenPBR material,
 * an .hdr / .exr the environment (useEnvironment(name, pixels)); a file refused is said why in a notice. Returns
 * whether it was taken.
 */
function takeFile(name, buffer, { measured, useEnvironment, openpbr, notices }) {
  if (/\.mtlx$/i.test(name)) {
    return openpbr.load(name, buffer instanceof ArrayBuffer ? new TextDecoder().decode(buffer) : null);
  }
  if (/\.binary$/i.test(name)) {
    const mb = MAX_FILE_BYTES / 2 ** 20;
    if (!(buffer instanceof ArrayBuffer)) notices.show(`${name}: larger than ${mb} MB. Kept the material.`);
    else measured.load(name, buffer);
    return buffer instanceof ArrayBuffer;
  }
  let pixels;
  try {
    pixels = parseEnvironmentFile(name, buffer);
  } catch (e) {
    notices.show(`${e.message} Kept the current environment.`);
    return false;
  }
  useEnvironment(name, pixels);
  return true;
}

export const widget = { name: 'material-lab', schema, create: createMaterialLab, terms: TERMS_USED };
