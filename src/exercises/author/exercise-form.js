// The form of one exercise on the author page, for every kind the format has (docs/exercises.md): the fields every
// exercise shares, then a widget exercise's grader, parameters, tolerance and widget (with the widget itself to set
// up the state and the locks), or a shader exercise's fields (shader-fields.js). The form is rebuilt from the
// exercise when its shape changes (another kind, grader, widget, slot or term); typing only reads it.
import { CHAPTERS } from '../../widgets/chapters.js';
import { GRADERS } from '../graders.js';
import { WIDGETS } from '../../widgets/registry.js';
import {
  KINDS,
  fieldFor,
  gradersOf,
  kindOf,
  newExercise,
  pathOf,
  readNumber,
  setPath,
  shaderDefaults,
} from './draft.js';
import { el, field, numberInput, select, showErrors, textArea, textInput } from './fields.js';
import { plotDefault, shaderFields } from './shader-fields.js';
import { createWidgetSetup } from './widget-setup.js';

const chapterOptions = Object.fromEntries(CHAPTERS.map((c, i) => [c.key, `${i + 1}. ${c.title}`]));

/** A field of a grader's params schema (state.js kinds): a select for an enum, a number box otherwise. */
function paramField(key, f, value, graderName) {
  const control =
    f.type === 'enum'
      ? select(f.options, value, f.required ? null : `default (${f.options[f.default] ?? f.default})`)
      : numberInput(value);
  const range = f.type === 'number' ? `, ${f.min}…${f.max}` : '';
  const need = f.required ? 'required' : `optional, default ${f.default}`;
  const meaning = `A parameter of “${GRADERS[graderName].title}” (${need}${range}).`;
  const read = () => (f.type === 'enum' ? control.value || undefined : readNumber(control.value));
  return field(`params.${key}`, f.label ?? key, meaning, control, read);
}

const MEANING = {
  kind: 'How the student answers.',
  id: 'Lower-case letters, digits and dashes; unique in the set. The exercise’s #anchor and its progress key.',
  chapter: 'Where the list files it.',
  title: 'Shown in the list and above the question.',
  points: 'What solving it is worth in the score (above 0, at most 100; 1 when left empty).',
  prompt: 'Plain text, never HTML; a formula between dollars is TeX: $\\alpha = 0.5$ (a literal dollar is \\$).',
};

/** The fields every exercise has. */
function sharedFields(raw, kind) {
  const id = textInput(raw.id);
  const chapter = select(chapterOptions, raw.chapter);
  const title = textInput(raw.title);
  const prompt = textArea(raw.prompt, 4);
  const points = numberInput(raw.points);
  const kindSelect = select(KINDS, kind);
  kindSelect.dataset.shape = 'kind';
  const text = (box) => () => box.value.trim() || undefined;
  return [
    field('kind', 'Kind', MEANING.kind, kindSelect, () => (kindSelect.value === 'shader' ? 'shader' : undefined)),
    field('id', 'Id', MEANING.id, id, text(id)),
    field('chapter', 'Chapter', MEANING.chapter, chapter, () => chapter.value),
    field('title', 'Title', MEANING.title, title, text(title)),
    field('prompt', 'Question', MEANING.prompt, prompt, text(prompt)),
    field('points', 'Points', MEANING.points, points, () => readNumber(points.value)),
  ];
}

/** The grader, its parameters, the tolerance and the widget of a number, choice or state exercise. */
function graderFields(raw, kind) {
  const names = gradersOf(kind);
  const name = names.includes(raw.grader) ? raw.grader : names[0];
  const grader = GRADERS[name];
  const graderSelect = select(Object.fromEntries(names.map((n) => [n, GRADERS[n].title])), name);
  graderSelect.dataset.shape = 'grader';
  const tolerance = numberInput(raw.tolerance);
  const fixed = grader.widget;
  const widgets = fixed
    ? { [fixed]: WIDGETS[fixed].title }
    : Object.fromEntries(Object.entries(WIDGETS).map(([k, w]) => [k, w.title]));
  const widget = select(widgets, raw.widget ?? (fixed || ''), fixed ? null : 'none');
  widget.dataset.shape = 'widget';
  const params = Object.entries(grader.params).map(([key, f]) => paramField(key, f, raw.params?.[key], name));
  const what = `${grader.summary.replace(/`/g, '')} It computes the answer when the student checks: none is stored.`;
  const widgetWords = fixed
    ? `This grader reads the ${WIDGETS[fixed].title} widget.`
    : 'Shown under the question (optional for this grader).';
  return [
    field('grader', 'Grader', what, graderSelect, () => name),
    ...params,
    field('tolerance', 'Tolerance', `A positive number: ${grader.tolerance}.`, tolerance, () =>
      readNumber(tolerance.value),
    ),
    field('widget', 'Widget', widgetWords, widget, () => widget.value || undefined),
  ];
}

/** The exercise after a change of its kind, grader, widget, slot, reference term or plot: { next, kind }. */
function reshape(raw, shape, target) {
  const value = target.value;
  if (shape === 'kind') {
    const { id, chapter, title, prompt, points } = raw;
    return { next: { ...newExercise(value, 0), id, chapter, title, prompt, points }, kind: value };
  }
  const kind = kindOf(raw);
  const changed = {
    grader: () => ({ ...raw, grader: value, params: {}, widget: GRADERS[value].widget ?? raw.widget }),
    widget: () => ({ ...raw, widget: value || undefined, state: {}, locked: [] }),
    slot: () => ({ ...raw, ...shaderDefaults(value), plot: undefined }),
    term: () => ({ ...raw, reference: { term: value } }),
    plot: () => ({ ...raw, plot: target.checked ? plotDefault(raw) : undefined }),
  };
  return { next: changed[shape](), kind };
}

/**
 * parent: where the form goes; schemaOf(name); onInput(raw) after each edit (typing, a widget's change).
 * Returns { edit(raw, kind), read() → raw, show(errors) → the messages no field took }.
 */
export function createExerciseForm(parent, { schemaOf, onInput }) {
  const form = el('form', { className: 'author-form', noValidate: true });
  form.addEventListener('submit', (e) => e.preventDefault());
  parent.append(form);
  let fields = [];
  let setup = null; // the widget setup, kept while its widget stays

  const read = () => {
    const out = {};
    for (const f of fields) setPath(out, f.path, f.read());
    if (setup) {
      const { state, locked } = setup.read();
      if (Object.keys(state).length) out.state = state;
      if (locked.length) out.locked = locked;
    }
    return out;
  };

  function build(raw, kind) {
    const shapeOf = kind === 'shader' ? shaderFields(raw) : graderFields(raw, kind);
    fields = [...sharedFields(raw, kind), ...shapeOf];
    const widget = kind === 'shader' ? null : (fields.find((f) => f.path === 'widget').read() ?? null);
    if (setup?.name !== widget) {
      setup?.dispose();
      setup = widget
        ? {
            name: widget,
            ...createWidgetSetup({
              name: widget,
              state: raw.state ?? {},
              locked: raw.locked ?? [],
              schemaOf,
              onChange: () => onInput(read()),
            }),
          }
        : null;
    }
    const boxes = fields.filter((f) => !f.inside).map((f) => f.box);
    if (setup) boxes.push(setup.stateBox, setup.lockBox);
    form.replaceChildren(...boxes);
  }

  // a change of shape: the exercise as read, changed, and the form built again around it
  form.addEventListener('change', (e) => {
    const target = /** @type {HTMLInputElement} */ (e.target);
    const shape = target.dataset?.shape;
    if (!shape) return;
    const { next, kind } = reshape(read(), shape, target);
    build(next, kind);
    /** @type {HTMLElement} */ (form.querySelector(`[data-shape="${shape}"]`))?.focus();
    onInput(read());
  });
  form.addEventListener('input', (e) => {
    if (!(/** @type {HTMLElement} */ (e.target).dataset?.shape)) onInput(read());
  });

  return {
    edit(raw, kind = kindOf(raw)) {
      setup?.dispose();
      setup = null;
      build(raw, kind);
    },
    read,
    /** Puts each message beside the field it names; returns those that name no field of the form. */
    show(errors) {
      const boxes = [...form.querySelectorAll('[data-field]')];
      const paths = boxes.map((b) => b.dataset.field);
      const byPath = new Map(paths.map((p) => [p, []]));
      const rest = [];
      for (const e of errors) {
        const at = fieldFor(pathOf(e) ?? '', paths);
        if (at) byPath.get(at).push(e);
        else rest.push(e);
      }
      for (const b of boxes) showErrors(b, byPath.get(b.dataset.field));
      return rest;
    },
    dispose() {
      setup?.dispose();
      form.remove();
    },
  };
}
