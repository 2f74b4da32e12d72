// A shader exercise on the page: the slot's signature and sources, the code editor with the starter, Check, the
// feedback (the worst input, or the problems at the student's lines, marked in the editor too) and a plot of
// the student's curve against the reference. Grading is injected: grade(code) → Promise of gradeShader's result.
import './shader-exercise.css';
import { createPlot } from '../core/ui/plot.js';
import { seriesStyle } from '../core/ui/palettes.js';
import { termLabel } from '../math/catalogue/index.js';
import { GRADED_SLOTS } from './shader-slots.js';
import { fmtInput } from './shader-grader.js';
import { SLOTS } from '../core/custom/slots.js';

const el = (tag, props = {}, ...children) => {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
};

/** A log axis over whole decades around the positive values, at most 8 decades below the largest; null: none. */
function logRange(values) {
  const positive = values.filter((v) => Number.isFinite(v) && v > 0);
  if (!positive.length) return null;
  const top = Math.ceil(Math.log10(Math.max(...positive)));
  const bottom = Math.max(Math.floor(Math.log10(Math.min(...positive))), top - 8);
  return { log: true, min: 10 ** bottom, max: 10 ** Math.max(top, bottom + 1) };
}

/** The plot spec of a graded curve; on a log axis, values ≤ 0 are gaps. */
function curveSpec(exercise, curve) {
  const slot = GRADED_SLOTS[exercise.slot];
  const yLog = exercise.plot.logY ? logRange([...curve.yours, ...curve.reference]) : null;
  const log = yLog !== null;
  const y = (v) => (Number.isFinite(v) && (!log || v > 0) ? v : null);
  const at = Object.entries(exercise.plot.at)
    .map(([name, v]) => `${slot.axes[name].label} = ${fmtInput(v)}`)
    .join(', ');
  return {
    title: `Your ${slot.value} against ${termLabel(slot.family, exercise.reference.term)}, at ${at}`,
    xLabel: curve.xLabel,
    yLabel: slot.value,
    x: { min: curve.x[0], max: curve.x[curve.x.length - 1] },
    y: yLog,
    series: [
      { label: `yours`, ...seriesStyle(1), width: 2 },
      { label: 'reference', ...seriesStyle(0), width: 2 },
    ],
    data: [curve.x, curve.yours.map(y), curve.reference.map(y)],
    height: 240,
    filename: `${exercise.id}-curve`,
  };
}

/**
 * Shows `exercise` in `parent`. options: createEditor(parent, { doc, label }) → CodeEditor (code-editor.js),
 * grade(code) → Promise<result>, onGraded(result) after each Check. Returns { editor, dispose() }.
 */
export function createShaderExercise(parent, exercise, { createEditor, grade, onGraded }) {
  const slot = GRADED_SLOTS[exercise.slot];
  const sources = el('p', { className: 'exercise-sources', textContent: `Sources: ${exercise.sources.join('; ')}.` });
  const signature = el('p', {}, 'Write ', el('code', { textContent: SLOTS[exercise.slot].signature }), ':');
  const label = `Your ${slot.value}: GLSL code of the ${exercise.slot} slot`;
  const editorHolder = el('div', { className: 'exercise-code' });
  const check = el('button', { type: 'button', className: 'exercise-check', textContent: 'Check' });
  const feedback = el('div', { className: 'exercise-feedback', role: 'status' });
  feedback.setAttribute('aria-live', 'polite');
  const plotHolder = el('div', { className: 'exercise-curve' });
  parent.append(
    sources,
    signature,
    editorHolder,
    el('div', { className: 'exercise-form' }, check),
    feedback,
    plotHolder,
  );
  const editor = createEditor(editorHolder, { doc: exercise.starter, label });
  let plot = null;
  let disposed = false;

  const show = (result) => {
    feedback.className = `exercise-feedback ${result.passed ? 'ok' : 'wrong'}`;
    const details = result.details.map((d) => el('li', { textContent: d }));
    feedback.replaceChildren(
      el('p', { textContent: result.summary }),
      ...(details.length ? [el('ul', {}, ...details)] : []),
    );
    editor.setDiagnostics(result.problems ?? []);
    if (!result.curve) return;
    const spec = curveSpec(exercise, result.curve);
    if (plot) plot.setData(spec);
    else plot = createPlot(plotHolder, spec);
  };

  check.addEventListener('click', async () => {
    check.disabled = true;
    feedback.className = 'exercise-feedback';
    feedback.replaceChildren(el('p', { textContent: 'Running your code on the GPU…' }));
    const result = await grade(editor.value);
    if (disposed) return;
    check.disabled = false;
    show(result);
    onGraded(result);
  });

  return {
    editor,
    dispose() {
      disposed = true;
      plot?.dispose();
      editor.destroy();
    },
  };
}
