// The exercises page: the list by chapter with progress, one exercise at a time (prompt, the grader's
// pictures, the widget with its locked controls, an answer, Check, feedback; or, for a shader exercise, the code
// editor graded on the GPU). The set comes from exercises/index.json, from ?src=URL, or from a dropped file; a
// bad file shows its errors, nothing throws. In an iframe it tells its parent each Check's result (`origins=`).
import '../styles.css';
import '../exercises/exercise-list.css';
import { CHAPTERS } from './chapters.js';
import { mountOrExplain } from '../core/framework/widget-failure.js';
import { isOption } from '../core/framework/state.js';
import { WIDGETS, isWidgetName } from '../widgets/registry.js';
import { GRADERS } from '../exercises/graders.js';
import { loadExerciseSet, readExerciseFile } from '../exercises/load.js';
import { createProgress, memoryStorage } from '../exercises/progress.js';
import { createProgressPanel } from '../exercises/progress-panel.js';
import { parseNumberAnswer } from '../exercises/answer.js';
import { createPreview } from '../exercises/previews.js';
import { hashId } from '../core/framework/url-hash.js';
import { onFileDrop } from '../core/ui/file-drop.js';
import { setInlineTex } from '../core/ui/inline-tex.js';
import { typesetFormulas } from '../core/framework/formulas.js';
import { publish, unregisterWidget } from '../core/framework/debug-hooks.js';
import { createGradedLink } from '../exercises/graded-message.js';
import { startPackageMode } from '../exercises/scorm/package-mode.js';
import { createAnswerControls } from '../exercises/answer-controls.js';
import { drawsHidden, hiddenFor, readSeed } from '../exercises/question-seed.js';

const listEl = document.getElementById('exercise-list');
const listBox = /** @type {HTMLDetailsElement} */ (document.getElementById('exercise-list-box'));
const listSummary = document.getElementById('exercise-list-summary');
// a phone folds the list into one line above the exercise (exercise-list.css); a wide screen keeps it open beside it
const narrow = matchMedia('(max-width: 820px)');
const foldList = () => (listBox.open = !narrow.matches);
narrow.addEventListener('change', foldList);
foldList();
const articleEl = document.getElementById('exercise');
const problemsEl = document.getElementById('exercise-problems');
const pageParams = new URLSearchParams(location.search);
// in a SCORM package (?scorm=1) progress goes to the LMS, once the set's ids are known (useSet)
const scorm = pageParams.get('scorm') === '1' ? startPackageMode({ place: problemsEl }) : null;
// the author page's preview (?preview=1) is answered as a student would, without touching the lecturer's progress
const preview = pageParams.get('preview') === '1';
let progress = createProgress(preview ? memoryStorage() : undefined); // in package mode replaced by useSet
// the preview shows the exercise, not the page's introduction or the student's own sections
if (preview) for (const part of document.querySelectorAll('.exercise-own, main > h1, main > .lede')) part.hidden = true;
if (scorm?.lms)
  document.getElementById('exercise-progress-where').textContent =
    'Your progress goes to your course’s learning management system (LMS), which keeps it for your next visit.';
let setTitle = null;
const gradedLink = createGradedLink(pageParams);

const schemaOf = async (name) => (isWidgetName(name) ? (await WIDGETS[name].load()).widget.schema : null);
const el = (tag, props = {}, ...children) => {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
};

// a bad `origins=` entry is said on the page (the rest of the list still counts)
if (gradedLink.notices.length)
  problemsEl.before(el('div', { className: 'notice' }, ...gradedLink.notices.map((n) => el('p', { textContent: n }))));

// the question number of exercises with a hidden part: from the address, else drawn (and then written there)
const firstSeed = readSeed(pageParams.get('seed'));
let seed = firstSeed.seed;
if (firstSeed.problem)
  problemsEl.before(el('div', { className: 'notice' }, el('p', { textContent: firstSeed.problem })));

let exercises = [];
let current = null; // { exercise, widget, preview, hidden }

function showProblems(problems) {
  problemsEl.replaceChildren(
    ...problems.map(({ source, errors }) =>
      el(
        'div',
        { className: 'notice notice-error' },
        el('strong', { textContent: `${source}: ${errors.length} problem${errors.length > 1 ? 's' : ''}, not loaded` }),
        el('ul', {}, ...errors.map((e) => el('li', { textContent: e }))),
      ),
    ),
  );
}

function renderList() {
  const solved = exercises.filter((e) => progress.of(e.id).solved).length;
  const summary = el(
    'p',
    { className: 'exercise-progress' },
    el('progress', { max: exercises.length || 1, value: solved }),
    ` ${solved} of ${exercises.length} solved`,
  );
  summary.firstChild.setAttribute('aria-label', 'Exercises solved');
  const reset = el('button', { type: 'button', className: 'exercise-reset', textContent: 'Reset progress' });
  reset.addEventListener('click', () => {
    if (!confirm('Forget which exercises you solved and how many attempts you made?')) return;
    progress.reset();
    renderList();
    if (current) renderStatus();
  });
  const groups = CHAPTERS.filter((ch) => exercises.some((e) => e.chapter === ch.key)).map((ch) => {
    const items = exercises
      .filter((e) => e.chapter === ch.key)
      .map((e) => {
        const p = progress.of(e.id);
        const a = el('a', { href: `#${e.id}`, textContent: e.title });
        if (current?.exercise.id === e.id) a.setAttribute('aria-current', 'true');
        const status = p.solved ? '✓ solved' : p.attempts ? `${p.attempts} attempt${p.attempts > 1 ? 's' : ''}` : '';
        return el(
          'li',
          { className: p.solved ? 'solved' : '' },
          a,
          status ? el('span', { className: 'exercise-status', textContent: ` ${status}` }) : '',
        );
      });
    return el(
      'section',
      {},
      el('h2', { textContent: `${CHAPTERS.indexOf(ch) + 1}. ${ch.title}` }),
      el('ol', {}, ...items),
    );
  });
  listEl.replaceChildren(summary, reset, ...groups);
  const now = current ? ` · now: ${current.exercise.title}` : '';
  listSummary.textContent = `All exercises (${solved} of ${exercises.length} solved)${now}`;
}

function renderStatus() {
  const p = progress.of(current.exercise.id);
  articleEl.querySelector('.exercise-meta').textContent = p.solved
    ? `Solved${p.attempts ? ` (${p.attempts} attempt${p.attempts > 1 ? 's' : ''})` : ''}`
    : p.attempts
      ? `Not solved yet: ${p.attempts} attempt${p.attempts > 1 ? 's' : ''}`
      : 'Not tried yet';
}

/** The answer part of the form: a number box, a group of options, or a note that the widget is the answer. */
function answerField(exercise, grader) {
  const a = grader.answer;
  if (a.kind === 'number') {
    const input = el('input', {
      type: 'text',
      inputMode: 'decimal',
      name: 'answer',
      id: 'exercise-answer',
      autocomplete: 'off',
      required: true,
    });
    const label = el('label', { htmlFor: 'exercise-answer', textContent: `${a.label}${a.unit ? ` (${a.unit})` : ''}` });
    return { node: el('div', { className: 'exercise-answer' }, label, input), read: () => input.value.trim() };
  }
  if (a.kind === 'choice') {
    const options = Object.entries(a.choices(exercise.params)).map(([value, text]) =>
      el('label', {}, el('input', { type: 'radio', name: 'answer', value }), ` ${text}`),
    );
    const fieldset = el(
      'fieldset',
      { className: 'exercise-answer' },
      el('legend', { textContent: 'Your answer' }),
      ...options,
    );
    return { node: fieldset, read: () => fieldset.querySelector('input:checked')?.value ?? '' };
  }
  // the sliders of the keys the grader reads join `controls` once the widget is up (answer-controls.js)
  const controls = el('div', { className: 'exercise-controls' });
  const note = el('p', { textContent: 'Answer with the slider here or the widget’s own controls, then check.' });
  return { node: el('div', { className: 'exercise-answer' }, note, controls), read: () => null, controls };
}

/** Grades the current answer; null when there is nothing to grade yet (an empty or unreadable box). */
function check(read) {
  const { exercise, widget, hidden } = current;
  const grader = GRADERS[exercise.grader];
  const raw = read();
  let answer = raw;
  if (grader.answer.kind === 'number') {
    answer = parseNumberAnswer(raw);
    if (raw === '' || !Number.isFinite(answer))
      return {
        ok: false,
        counted: false,
        summary: `Enter a number${grader.answer.unit ? ` in ${grader.answer.unit}` : ''}.`,
        details: [],
      };
  }
  if (grader.answer.kind === 'choice' && !isOption(grader.answer.choices(exercise.params), raw)) {
    return { ok: false, counted: false, summary: 'Pick one of the options.', details: [] };
  }
  try {
    const result = grader.grade({
      state: widget?.getState() ?? {},
      answer,
      params: exercise.params,
      tolerance: exercise.tolerance,
      hidden,
    });
    return { ...result, counted: true };
  } catch (e) {
    return {
      ok: false,
      counted: false,
      summary: `The grader could not check this answer (${e.message}).`,
      details: [],
    };
  }
}

/** The exercises in the list's order: by chapter, then as the set lists them. */
const inListOrder = () => CHAPTERS.flatMap((ch) => exercises.filter((e) => e.chapter === ch.key));

/** The exercise to offer after `id`: the next one in the list not solved yet (from the top again), or null. */
function nextAfter(id) {
  const list = inListOrder();
  const at = list.findIndex((e) => e.id === id);
  const after = [...list.slice(at + 1), ...list.slice(0, Math.max(at, 0))];
  return after.find((e) => !progress.of(e.id).solved) ?? null;
}

/** A solved exercise's feedback ends with a link to the next one (the Tab after Check reaches it). */
function offerNext(box, id) {
  const next = nextAfter(id);
  box.append(
    next
      ? el(
          'p',
          { className: 'exercise-next' },
          el('a', { href: `#${next.id}`, textContent: `Next exercise: ${next.title}` }),
        )
      : el('p', { className: 'exercise-next', textContent: 'That was the last one not yet solved: all are solved.' }),
  );
}

function showFeedback(box, result) {
  box.className = `exercise-feedback ${result.ok ? 'ok' : 'wrong'}`;
  box.replaceChildren(
    el('p', { textContent: result.summary }),
    ...(result.details.length ? [el('ul', {}, ...result.details.map((d) => el('li', { textContent: d })))] : []),
  );
  if (result.ok) offerNext(box, current.exercise.id);
}

/** After each counted Check of a new answer: progress, the list, and the parent frame told. */
function recordCheck(id, passed, score, answer) {
  if (!progress.record(id, passed, answer)) return;
  renderStatus();
  renderList();
  gradedLink.graded({ id, passed, score });
}

/** The prompt, its `$…$` formulas typeset (as text and MathML: a prompt from a URL is never HTML). */
function promptOf(exercise) {
  const prompt = el('p', { className: 'exercise-prompt' });
  setInlineTex(prompt, exercise.prompt);
  typesetFormulas(prompt);
  return prompt;
}

/** A chosen exercise's heading takes the focus and the top of the window: the question and Check below it. */
function focusHeading(heading) {
  heading.focus({ preventScroll: true });
  heading.scrollIntoView({ block: 'start' });
}

/** The parts every exercise shows first: chapter, title, progress line and prompt. */
function exerciseHeader(exercise) {
  const heading = el('h2', { tabIndex: -1, textContent: exercise.title });
  const chapter = CHAPTERS.find((c) => c.key === exercise.chapter);
  const parts = [
    el('p', {
      className: 'exercise-chapter',
      textContent: `Chapter ${CHAPTERS.indexOf(chapter) + 1}: ${chapter.title}`,
    }),
    heading,
    el('p', { className: 'exercise-meta' }),
    promptOf(exercise),
  ];
  return { heading, parts };
}

/** A shader exercise: the editor (loaded on demand with the GPU grader), Check, feedback and the curve. */
async function openShaderExercise(exercise, { focus }) {
  current = { exercise, widget: null, preview: null, hidden: undefined };
  publish('exercise', { id: exercise.id, ready: false });
  const { heading, parts } = exerciseHeader(exercise);
  const body = el('div', { className: 'exercise-shader' });
  articleEl.replaceChildren(...parts, body);
  renderStatus();
  renderList();
  if (focus) focusHeading(heading);
  const mine = current;
  const [{ createCodeEditor }, { gradeOnGpu }, { createShaderExercise }] = await Promise.all([
    import('../core/ui/code-editor.js'),
    import('../exercises/gpu-grade.js'),
    import('../exercises/shader-view.js'),
  ]);
  if (current !== mine) return; // another exercise was opened meanwhile
  let graded = '';
  current.preview = createShaderExercise(body, exercise, {
    createEditor: createCodeEditor,
    grade: (code) => gradeOnGpu(exercise, (graded = code)),
    onGraded: (result) => {
      if (result.counted !== false) recordCheck(exercise.id, result.passed, result.score, graded);
      if (result.passed) offerNext(body.querySelector('.exercise-feedback'), exercise.id);
    },
  });
  publish('exercise', { id: exercise.id, ready: true });
}

function closeCurrent() {
  current?.widget?.dispose();
  current?.preview?.dispose?.();
  unregisterWidget('exercise');
  current = null;
}

/** The line that says which question is shown (its seed, kept in the address) and draws another one. */
function seedLine(exercise) {
  const url = new URL(location.href);
  url.searchParams.set('seed', String(seed));
  history.replaceState(history.state, '', url);
  const again = el('button', { type: 'button', className: 'exercise-again', textContent: 'Another question' });
  again.addEventListener('click', () => {
    seed = readSeed(null).seed;
    openExercise(exercise, { focus: true });
  });
  const text = `Question ${seed} (seed=${seed} in this page’s address: a reload or the same link shows it again). `;
  return el('p', { className: 'exercise-seed' }, text, again);
}

/** The form's sliders for the keys a state exercise's grader reads, tied to the widget both ways. */
function answerControls(parent, { exercise, grader, schema, widget }) {
  return createAnswerControls(parent, {
    schema,
    keys: grader.reads ?? [],
    locked: exercise.locked,
    state: widget.getState(),
    onInput: (partial) => widget.update(partial),
  });
}

async function openExercise(exercise, { focus = false } = {}) {
  closeCurrent();
  if (exercise.kind === 'shader') return openShaderExercise(exercise, { focus });
  const grader = GRADERS[exercise.grader];
  const hidden = hiddenFor(grader, exercise.params, seed);
  current = { exercise, widget: null, preview: null, hidden };
  // for tests: what a hidden question drew, and when it is up
  publish('exercise', { id: exercise.id, hidden, ready: false });
  const { heading, parts } = exerciseHeader(exercise);
  const pictures = el('div', { className: 'exercise-pictures' });
  const field = answerField(exercise, grader);
  const feedback = el('div', { className: 'exercise-feedback', role: 'status' });
  feedback.setAttribute('aria-live', 'polite');
  const form = el(
    'form',
    { className: 'exercise-form' },
    field.node,
    el('button', { type: 'submit', className: 'exercise-check', textContent: 'Check' }),
  );
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    const result = check(field.read);
    const answer = JSON.stringify([field.read(), current.widget?.getState() ?? null]);
    if (result.counted) recordCheck(exercise.id, result.ok, result.ok ? 1 : 0, answer);
    showFeedback(feedback, result);
  });
  const slot = el('div', { className: 'exercise-widget' });
  const question = drawsHidden(grader, exercise.params) ? [seedLine(exercise)] : [];
  articleEl.replaceChildren(...parts, ...question, pictures, form, feedback, slot);
  renderStatus();
  renderList();
  if (focus) focusHeading(heading); // a chosen exercise takes the focus; the first one shown on load does not
  current.preview = createPreview(pictures, exercise, hidden);
  if (!exercise.widget) {
    publish('exercise', { id: exercise.id, hidden, ready: true });
    return;
  }
  // read once, before the mount (a widget whose chunk fails is explained in its place by the mount)
  const schema = await schemaOf(exercise.widget).catch(() => null);
  const mine = current;
  const widget = await mountOrExplain(slot, exercise.widget, {
    widgets: WIDGETS,
    prefix: 'exercise',
    syncUrl: false,
    state: exercise.state,
    locked: exercise.locked,
    onStateChange: (state) => {
      mine.preview?.update(state);
      mine.controls?.sync(state);
    },
  });
  if (!widget) return; // it says why in its place, with Retry
  if (current !== mine) return widget.dispose(); // another exercise was opened meanwhile
  if (schema && exercise.locked.length) {
    const names = exercise.locked.map((k) => schema[k].label ?? k);
    slot.prepend(
      el('p', {
        className: 'exercise-locked',
        textContent: `Fixed by the exercise (grey, framed in dashes and marked “fixed” below): ${names.join(', ')}.`,
      }),
    );
  }
  current.widget = widget;
  if (schema && field.controls) current.controls = answerControls(field.controls, { exercise, grader, schema, widget });
  current.preview?.update(widget.getState());
  publish('exercise', { id: exercise.id, hidden, ready: true });
}

function route(event) {
  const id = hashId();
  const exercise = exercises.find((e) => e.id === id) ?? exercises[0];
  if (!exercise) {
    closeCurrent();
    articleEl.replaceChildren(el('p', { textContent: 'No exercises to show.' }));
    renderList();
    return;
  }
  if (event?.type === 'hashchange') foldList(); // a link picked in the unfolded list on a phone folds it again
  if (current?.exercise === exercise) {
    if (event?.type === 'hashchange') focusHeading(articleEl.querySelector('h2')); // the one shown, picked again
    return;
  }
  openExercise(exercise, { focus: event?.type === 'hashchange' });
}

function useSet({ exercises: list, problems, title = null, passMark = null }) {
  exercises = list;
  setTitle = title;
  const points = Object.fromEntries(list.map((e) => [e.id, e.points]));
  if (scorm)
    progress = createProgress(
      scorm.storageFor(
        list.map((e) => e.id),
        { points, passMark },
      ),
    );
  showProblems(problems);
  closeCurrent();
  route();
}

window.addEventListener('hashchange', route);

createProgressPanel(document, {
  state: () => ({ exercises, progress, title: setTitle }),
  onLoaded: () => {
    renderList();
    if (current) renderStatus();
  },
  lms: Boolean(scorm?.lms),
});

// A lecturer's own file, chosen or dropped: it replaces the list shown.
const readFile = async (file) => useSet(await readExerciseFile(file, { schemaOf }));
onFileDrop(document.getElementById('exercise-drop'), readFile, { input: document.getElementById('exercise-file') });

const src = pageParams.get('src');
useSet(await loadExerciseSet(src || 'exercises/index.json', { schemaOf }));
