// The material lab's OpenPBR Surface panel, under the images: the presets (each with its source), a .mtlx file
// loaded (src/lab/mtlx/: constant inputs only, size- and depth-capped; a refusal is said here and the material kept)
// or saved, and the bars of what each layer adds: under the punctual light (the mean over the sphere) and in the
// white furnace (each layer's directional albedo, and what the stack with every colour white loses). The bars are
// computed a moment after the material stops changing, off the frame a slider's drag waits for.
import { readMtlx, writeMtlx, mtlxName } from '../../lab/mtlx/mtlx.js';
import { OPENPBR_LAYERS, savedOpenPbr, openPbrOfState, stateOfOpenPbr } from '../../lab/openpbr-lab.js';
import { OPENPBR_PRESETS } from '../../lab/openpbr-presets.js';
import { PARTS, openPbrFurnace, openPbrLightBreakdown, whiteStack } from '../../lab/openpbr-breakdown.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { download } from '../../core/framework/download.js';
import { createSettledTask } from '../../core/framework/render-loop.js';
import { watchHeldInput } from '../../core/framework/held-input.js';

const PART_WORDS = {
  diffuse: 'base diffuse',
  specular: 'specular (dielectric gloss)',
  metal: 'metal',
  coat: 'coat',
  fuzz: 'fuzz',
};
const luminance = ([r, g, b]) => 0.2126 * r + 0.7152 * g + 0.0722 * b;

const el = (tag, props = {}, ...children) => {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
};

/** One stacked bar: each part's share of `parts` (luminance), its legend with the figures. */
function barOf(title, parts, unit) {
  const values = PARTS.map((p) => [p, luminance(parts[p])]);
  const total = values.reduce((s, [, x]) => s + x, 0);
  const bar = el('div', { className: 'openpbr-bar' });
  bar.setAttribute('role', 'img');
  const legend = el('ul', { className: 'openpbr-legend' });
  for (const [p, x] of values) {
    if (!(x > 0)) continue;
    const share = x / total;
    bar.append(el('span', { className: `openpbr-part openpbr-${p}`, style: `width: ${(100 * share).toFixed(2)}%` }));
    legend.append(
      el(
        'li',
        { className: `openpbr-key-${p}` },
        el('span', { className: `openpbr-swatch openpbr-${p}` }),
        `${PART_WORDS[p]}: ${x.toPrecision(3)}${unit} (${(100 * share).toFixed(1)} %)`,
      ),
    );
  }
  const said = [...legend.children].map((li) => li.textContent).join('; ');
  bar.setAttribute('aria-label', `${title}: ${said || 'nothing'}`);
  return el('figure', { className: 'openpbr-figure' }, el('figcaption', {}, title), bar, legend);
}

/** The panel's elements; `onPreset(preset)`, `onFile(name, text or null)` and `onSave()` answer its buttons. */
function panelElements({ onPreset, onFile, onSave }) {
  const message = el('p', { className: 'openpbr-message' });
  message.setAttribute('role', 'status');
  const bars = el('div', { className: 'openpbr-bars' });
  const presets = el('div', { className: 'openpbr-presets' });
  const sources = el('ul', { className: 'openpbr-sources' });
  for (const [key, preset] of Object.entries(OPENPBR_PRESETS)) {
    const button = el('button', { type: 'button', textContent: preset.label, className: `openpbr-preset-${key}` });
    button.addEventListener('click', () => onPreset(preset));
    presets.append(button);
    sources.append(el('li', {}, el('strong', {}, `${preset.label}: `), preset.source));
  }
  const input = el('input', { type: 'file', accept: '.mtlx', className: 'visually-hidden', tabIndex: -1 });
  input.setAttribute('aria-label', LOAD_TEXT);
  const loadButton = el('button', { type: 'button', textContent: LOAD_TEXT, className: 'openpbr-load' });
  loadButton.addEventListener('click', () => input.click());
  input.addEventListener('change', async () => {
    const file = input.files?.[0];
    if (file) onFile(file.name, file.size > MAX_READ_BYTES ? null : await file.text());
    input.value = '';
  });
  const saveButton = el('button', {
    type: 'button',
    textContent: 'Save the material as .mtlx',
    className: 'openpbr-save',
  });
  saveButton.addEventListener('click', onSave);
  const element = el(
    'section',
    { className: 'openpbr-panel' },
    el('h3', {}, 'OpenPBR Surface'),
    el('p', {}, 'Presets (where each value comes from is listed under the bars):'),
    presets,
    el('div', { className: 'openpbr-files' }, loadButton, input, saveButton),
    message,
    bars,
    el('details', {}, el('summary', {}, 'Where the presets’ values come from'), sources),
  );
  return { element, message, bars };
}

const OFF_TEXT =
  'A preset, a loaded file or “OpenPBR Surface” as the BRDF renders the sphere with the material of the OpenPBR ' +
  'groups in the panel; the bars of what each layer adds then show here.';
const LOAD_TEXT = 'Load a MaterialX .mtlx file…';
const MAX_READ_BYTES = 4 * 2 ** 20; // not read at all beyond this; readMtlx's own cap is far below it

/**
 * The OpenPBR folders of the controls (`controls`, the lil-gui panel's container) stay as the user left them; when
 * OpenPBR is chosen with every one closed (they start closed, types.js), open() opens the one the user last worked
 * in, else the base, so that its controls are in view.
 */
function createFolderOpener(controls) {
  const GROUPS = Object.values(OPENPBR_LAYERS).map((l) => l.group);
  const titleOf = (folder) => folder.querySelector(':scope > .lil-title')?.textContent;
  const folders = () => [...controls.querySelectorAll('.lil-gui')].filter((f) => GROUPS.includes(titleOf(f)));
  let last = OPENPBR_LAYERS.base.group;
  const used = (e) => {
    const folder = e.target instanceof Element ? e.target.closest('.lil-gui') : null;
    if (folder && GROUPS.includes(titleOf(folder))) last = titleOf(folder);
  };
  controls.addEventListener('pointerdown', used);
  controls.addEventListener('focusin', used);
  return {
    open() {
      const all = folders();
      if (all.some((f) => !f.classList.contains('lil-closed'))) return; // one is open: the user's choice stands
      all
        .find((f) => titleOf(f) === last)
        ?.querySelector(':scope > .lil-title')
        ?.click();
    },
    dispose() {
      controls.removeEventListener('pointerdown', used);
      controls.removeEventListener('focusin', used);
    },
  };
}

/**
 * The bars of the material asked for last, drawn a moment after the asks pause and no gesture is held (`held()`):
 * ask(material, light), off() (OpenPBR not chosen), ready (the bars of the last ask are drawn), dispose().
 */
function createLaterBars(bars, held) {
  let next = null; // the bars asked for, { key, material, light }
  let pending = null; // the key of the bars scheduled
  let drawn = ''; // the key of the bars drawn
  const task = createSettledTask(() => {
    pending = null;
    drawn = next.key;
    bars.replaceChildren(...barsOf(next.material, next.light));
  });
  return {
    ask(material, light) {
      const key = JSON.stringify([material, light]);
      next = { key, material, light };
      if (key === drawn || held()) {
        // drawn already; or a drag's material, drawn at its end (the panel asks again then)
        task.cancel();
        pending = null;
      } else if (key !== pending) {
        pending = key;
        task.schedule();
      }
    },
    off() {
      task.cancel();
      if (drawn !== 'off') bars.replaceChildren(el('p', {}, OFF_TEXT));
      [drawn, next, pending] = ['off', null, null];
    },
    get ready() {
      return next !== null && drawn === next.key;
    },
    dispose: () => task.cancel(),
  };
}

/**
 * `shell` the lab's widget shell (its state, notices, controls), `update(patch)` sets the state, `onRelease()` runs
 * when a gesture held on the widget ends. Returns { element, material(state), refresh(state), load(name, text),
 * held(), api(), dispose }: material(state) is the OpenPBR material to render.
 */
export function createOpenPbrPanel({ shell, update, onRelease }) {
  const { notices, controls, root } = shell;
  const getState = () => shell.state;
  let [exact, name] = [{}, 'lab_material']; // the loaded file's colours, exact (openpbr-lab.js), and its name
  const { element, message, bars } = panelElements({
    onPreset: (preset) => use(preset.material, mtlxName(preset.label.toLowerCase()), preset.label),
    onFile: (fileName, text) => load(fileName, text),
    onSave: () => save(),
  });

  function use(material, fileName, label) {
    const state = stateOfOpenPbr(material);
    exact = state.exact;
    name = fileName;
    update({ ...state.patch, brdfSource: 'openpbr' });
    message.textContent = `${label} loaded.`;
  }

  /** A .mtlx file's text (null: too large to read): the material, or a message saying why not and the old kept. */
  function load(fileName, text) {
    try {
      if (text === null)
        throw new Error(`“${fileName}” is over ${MAX_READ_BYTES / 2 ** 20} MB; a material file is a few kilobytes.`);
      const read = readMtlx(text, fileName);
      let state;
      try {
        state = stateOfOpenPbr(read.material);
      } catch (error) {
        throw new Error(`“${fileName}” cannot be shown here: ${error.message}.`, { cause: error });
      }
      exact = state.exact;
      name = read.name || 'lab_material';
      update({ ...state.patch, brdfSource: 'openpbr' });
      const dropped = read.notKept.length ? ` Not kept (outside the lab's subset): ${read.notKept.join(', ')}.` : '';
      message.textContent = `Loaded “${fileName}” (${read.name || 'unnamed'}).${dropped}`;
      return true;
    } catch (error) {
      message.textContent = `${error.message} The material is kept as it was.`;
      notices.show(message.textContent);
      return false;
    }
  }

  /** The lab's material as a .mtlx document (every layer's weight as the sliders have it), handed to the reader. */
  function save() {
    const text = writeMtlx(savedOpenPbr(getState(), exact), name);
    download(`${mtlxName(name)}.mtlx`, new Blob([text], { type: 'application/xml' }));
    message.textContent = `Saved ${mtlxName(name)}.mtlx.`;
    return text;
  }

  const input = watchHeldInput(root, () => {
    onRelease();
    refresh(getState());
  });
  const later = createLaterBars(bars, () => input.held);
  let chosen = false; // whether OpenPBR was the BRDF at the last refresh
  const folders = createFolderOpener(controls);
  /** Draws the bars of `state`'s material again, a moment after it stops changing (and no gesture is held). */
  function refresh(state) {
    if (state.brdfSource === 'openpbr' && !chosen) folders.open(); // just chosen: its controls in view
    chosen = state.brdfSource === 'openpbr';
    if (!chosen) return later.off();
    const light = state.punctual ? [lightDirFromAngles(state.lightTheta, state.lightPhi), state.cLight] : null;
    later.ask(openPbrOfState(state, exact), light);
  }

  return {
    element,
    material: (state) => openPbrOfState(state, exact),
    refresh,
    load,
    /** What the widget gives the tests: the material rendered, whether the bars are drawn, load and save. */
    api: () => ({
      material: () => openPbrOfState(getState(), exact),
      get ready() {
        return later.ready;
      },
      load,
      save,
    }),
    /** Whether a gesture is held on the widget (OpenPBR's reference waits for its end: lab-frame.js). */
    held: () => input.held,
    dispose() {
      [later, folders, input].forEach((x) => x.dispose());
    },
  };
}

/** The bars: under the punctual light (when on), then the furnace head-on and at 60°, and the white stack's loss. */
function barsOf(material, light) {
  const out = [];
  if (light) {
    const [dir, c] = light;
    const parts = openPbrLightBreakdown(material, dir, [c, c, c]);
    out.push(barOf('Under the punctual light: each layer’s mean radiance over the sphere', parts, ''));
  } else out.push(el('p', {}, 'Switch the punctual light on to see what each layer adds under it.'));
  for (const [mu, words] of [
    [1, 'head-on (n·v = 1)'],
    [0.5, 'at 60° (n·v = 0.5)'],
  ]) {
    const e = openPbrFurnace(material, mu);
    const white = openPbrFurnace(whiteStack(material), mu).total;
    const title =
      `White furnace, ${words}: the material returns E = ${luminance(e.total).toFixed(3)} of the light; ` +
      `with every colour white the stack returns ${luminance(white).toFixed(3)}, losing ` +
      `${Math.max(0, 1 - luminance(white)).toFixed(3)} (the single-scattering lobes’ loss)`;
    out.push(barOf(title, e, ''));
  }
  return out;
}
