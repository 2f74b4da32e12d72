// @ts-check
// The panel of a user-written term: the code editor, the controls made from its slider lines, the live checks
// beside it, and what happened to the last edit (compile errors on the user's own lines while the last good code
// keeps drawing; code from a link waiting for one click; a lost graphics context). Edits reach the widget after a
// short pause in typing. A widget loads this module (and CodeMirror with it) only when a custom term is chosen.
import { createCodeEditor } from './code-editor.js';
import { SLOTS } from '../custom/slots.js';
import { parseCustom } from '../custom/parse.js';
import { runChecks } from '../custom/checks.js';
import { trustCode } from '../custom/custom-panel-trust.js';
import { sliderValues } from '../custom/custom-panel-run.js';
import { EDIT_DELAY_MS } from '../custom/custom-panel-delay.js';
import { createSliders } from './custom-panel-sliders.js';
import { createChecksView } from './custom-panel-checks.js';
import { cancelLater, later } from '../framework/debug-hooks.js';

/** @typedef {import('../custom/custom-panel-run.js').RunStatus} RunStatus */

export { createCustomRunner } from '../custom/custom-panel-run.js';

const CHECK_DELAY_MS = 400; // the checks run this long after the picture changed

/**
 * What the status line says for a run's status.
 * @param {RunStatus} status
 */
function statusText(status) {
  if (status.pending) return ''; // the consent box above the editor says it
  if (status.lost)
    return (
      status.lostMessage ??
      'The graphics context was lost: the picture keeps the last values read back; your code runs again when ' +
        'the context returns.'
    );
  if (status.suspect)
    return (
      'Your code was running when the GPU took the context away: it may run too long per pixel. The picture ' +
      'keeps the code before it; edit your code to run it again.'
    );
  if (status.problems.length)
    return status.ran
      ? 'Your last edit does not run (see the lines marked); the picture keeps your last good code.'
      : 'This code does not run (see the lines marked).';
  return status.ran ? 'Running your code.' : '';
}

/**
 * @param {string} tag
 * @param {string} className
 * @param {string} [text]
 */
function element(tag, className, text = '') {
  return Object.assign(document.createElement(tag), { className, textContent: text });
}

/** The panel's elements: a title, the code column (signature, consent, editor, status, problems) and a side column. */
/**
 * @param {HTMLElement} container
 * @param {import('../custom/slots.js').Slot} slot
 * @param {string} title
 */
function layout(container, slot, title) {
  const root = element('section', 'custom-panel');
  const heading = element('h3', 'custom-panel-title', title);
  const signature = element('code', 'custom-signature', slot.signature);
  const consent = element('div', 'custom-consent');
  const runButton = element('button', 'custom-run', 'Run this code');
  runButton.setAttribute('type', 'button');
  const why = 'This code came with the link or from the page around this one, and has not run in this browser.';
  consent.append(
    element('p', '', `${why} Read it, then run it; until then the picture keeps the code before it.`),
    runButton,
  );
  const status = element('p', 'custom-status');
  status.setAttribute('role', 'status');
  const problems = element('ul', 'custom-problems');
  const editorBox = element('div', 'custom-editor');
  const left = element('div', 'custom-panel-code');
  const right = element('div', 'custom-panel-side');
  left.append(signature, consent, editorBox, status, problems);
  root.append(heading, left, right);
  root.dataset.slot = slot.key;
  container.append(root);
  return { root, consent, runButton, status, problems, editorBox, right };
}

/**
 * @param {HTMLElement} container
 * @param {object} options
 * @param {'D' | 'V' | 'F' | 'diffuse' | 'brdf'} options.slotKey
 * @param {string} options.code  the state's code
 * @param {string} options.title  e.g. 'A: your D'
 * @param {() => any} options.getRenderer  the renderer the checks run on (null without one)
 * @param {(code: string) => void} options.onCode  the user's edit, after a pause in typing
 * @param {(name: string, value: number) => void} options.onParam  a slider moved
 * @param {() => void} options.onRun  the user accepted the code shown
 */
export function createCustomPanel(container, { slotKey, code, title, getRenderer, onCode, onParam, onRun }) {
  const slot = SLOTS[slotKey];
  const { root, consent, runButton, status, problems, editorBox, right } = layout(container, slot, title);

  let pendingEdit = 0;
  let lastSent = code;
  const editor = createCodeEditor(editorBox, {
    doc: code,
    label: `${title}: GLSL of ${slot.signature}`,
    onChange: (text) => {
      cancelLater(pendingEdit);
      pendingEdit = later(() => {
        pendingEdit = 0;
        lastSent = text;
        trustCode(text); // typed here: runs at once, and again after a reload of this link
        onCode(text);
      }, EDIT_DELAY_MS);
    },
  });
  const sliders = createSliders(right, onParam);
  let checksKey = '';
  let checksTimer = 0;
  /** @type {{ code: string, params: Record<string, number>, ran: string | null }} */
  let shown = { code, params: {}, ran: null };
  const checks = createChecksView(right, slot, () => scheduleChecks(true));
  runButton.addEventListener('click', () => {
    trustCode(editor.value);
    onRun();
  });

  function scheduleChecks(force = false) {
    const { ran, params } = shown;
    if (!ran) return checks.show('The checks run once your code runs.');
    const values = sliderValues(parseCustom(slotKey, ran).params, params);
    const key = JSON.stringify([ran, values, checks.reference]);
    if (key === checksKey && !force) return;
    checksKey = key;
    cancelLater(checksTimer);
    checksTimer = later(() => {
      const renderer = getRenderer();
      if (!renderer || renderer.getContext().isContextLost()) return checks.show('No graphics context: no checks.');
      checks.show(runChecks(renderer, slotKey, ran, values, { reference: checks.reference }));
    }, CHECK_DELAY_MS);
  }

  return {
    root,
    /**
     * After each draw of the widget: the state's code and slider values, and how the run went.
     * @param {{ code: string, params: Record<string, number>, status: RunStatus }} s
     */
    show({ code: stateCode, params, status: run }) {
      if (stateCode !== lastSent && !pendingEdit) editor.value = lastSent = stateCode; // from a URL or a parent
      const parsed = parseCustom(slotKey, stateCode);
      if (parsed.params.length || parsed.ok) sliders.show(parsed.params, sliderValues(parsed.params, params));
      consent.hidden = !run.pending;
      status.textContent = statusText(run);
      status.classList.toggle('custom-status-bad', Boolean(run.problems.length || run.lost || run.suspect));
      editor.setDiagnostics(run.problems);
      problems.replaceChildren(...run.problems.map((p) => element('li', '', `Line ${p.line}: ${p.message}`)));
      shown = { code: stateCode, params, ran: run.pending ? null : run.ran }; // no checks of code not shown
      scheduleChecks();
    },
    focus: () => editor.focus(),
    dispose() {
      cancelLater(pendingEdit);
      cancelLater(checksTimer);
      editor.destroy();
      checks.dispose();
      root.remove();
    },
  };
}
