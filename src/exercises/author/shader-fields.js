// The fields of a shader exercise on the author page: sources, the slot (its GLSL signature), the starter code,
// the catalogue term it is graded against with that term's fixed parameters, the input grid per axis, the
// tolerance and the optional plot. Each writes the field of docs/exercises.md that its validator messages name.
import { SLOTS } from '../../core/custom/slots.js';
import { CATALOGUE, termEntry, termOptions } from '../../math/catalogue/index.js';
import { GRADED_SLOTS, GRADED_SLOT_KEYS } from '../shader-slots.js';
import { readLines, readNumber, readNumberList } from './draft.js';
import { el, field, numberInput, select, textArea } from './fields.js';

const show = (list) => (list ?? []).join(', ');

/** One axis of the grid: its range (two boxes), steps and stress values, in a box of its own for its messages. */
function axisFields(name, axis, spec = {}) {
  const at = `domain.${name}`;
  const lo = numberInput(spec.range?.[0]);
  const hi = numberInput(spec.range?.[1]);
  lo.setAttribute('aria-label', `${axis.label} from`);
  hi.setAttribute('aria-label', `${axis.label} to`);
  const range = el('div', { className: 'author-group author-range' }, lo, ' to ', hi);
  const steps = numberInput(spec.steps);
  const stress = numberInput(show(spec.stress));
  const limits = `${axis.limits[0]}…${axis.limits[1]}`;
  const readRange = () => {
    const pair = [readNumber(lo.value), readNumber(hi.value)];
    return pair.every((v) => v === undefined) ? undefined : pair;
  };
  const parts = [
    field(
      `${at}.range`,
      `${axis.label}: range`,
      `Evenly spaced values over this range, ends included (within ${limits}).`,
      range,
      readRange,
    ),
    field(`${at}.steps`, `${axis.label}: steps`, 'How many values over the range (2–101).', steps, () =>
      readNumber(steps.value),
    ),
    field(
      `${at}.stress`,
      `${axis.label}: stress values`,
      `Up to 32 values that catch a typical mistake (within ${limits}), separated by spaces or “, ”.`,
      stress,
      () => readNumberList(stress.value),
    ),
  ];
  const errors = el('ul', { className: 'author-errors' });
  const box = el(
    'fieldset',
    { className: 'author-axis' },
    el('legend', { textContent: `Grid over ${axis.words}` }),
    errors,
    ...parts.map((p) => p.box),
  );
  box.dataset.field = at;
  // the parts are read with the others, but shown inside the axis's box
  return [{ path: at, box, read: () => undefined }, ...parts.map((p) => ({ ...p, inside: true }))];
}

/** The fixed parameters of the reference term that are not axes of the slot (F's η comes from F0 unless fixed). */
function referenceParamFields(slot, term, given = {}) {
  const family = GRADED_SLOTS[slot].family;
  if (!Object.hasOwn(CATALOGUE[family].terms, term)) return [];
  const entry = termEntry(family, term);
  return Object.entries(entry.params)
    .filter(([name]) => !Object.hasOwn(GRADED_SLOTS[slot].axes, name))
    .map(([name, p]) => {
      const box = numberInput(given[name]);
      const optional = slot === 'F' && name === 'eta' ? ' Optional: left empty, η follows from F0.' : '';
      return field(
        `reference.params.${name}`,
        `${term}: ${p.label ?? name}`,
        `A fixed value, ${p.min}…${p.max}.${optional}`,
        box,
        () => readNumber(box.value),
      );
    });
}

/** A plot's first x axis and the other axes at their lowest grid value. */
export function plotDefault(raw) {
  const axes = Object.keys(GRADED_SLOTS[raw.slot].axes);
  const at = Object.fromEntries(
    axes.slice(1).map((a) => [a, raw.domain?.[a]?.range?.[0] ?? raw.domain?.[a]?.stress?.[0] ?? 0.5]),
  );
  return { x: axes[0], at };
}

function plotFields(raw) {
  const on = el('input', { type: 'checkbox', checked: Boolean(raw.plot) });
  on.dataset.shape = 'plot';
  const out = [
    field(
      'plot',
      'Plot after Check',
      'Shows the student’s curve and the reference along one axis.',
      on,
      () => undefined,
    ),
  ];
  if (!raw.plot) return out;
  const axes = GRADED_SLOTS[raw.slot].axes;
  const x = select(Object.fromEntries(Object.entries(axes).map(([k, a]) => [k, a.label])), raw.plot.x);
  const logY = el('input', { type: 'checkbox', checked: Boolean(raw.plot.logY) });
  out.push(field('plot.x', 'Plot along', 'The axis across the plot.', x, () => x.value));
  for (const name of Object.keys(axes).filter((a) => a !== raw.plot.x)) {
    const box = numberInput(raw.plot.at?.[name]);
    out.push(
      field(`plot.at.${name}`, `Plot at ${axes[name].label}`, 'The value of this axis along the plot.', box, () =>
        readNumber(box.value),
      ),
    );
  }
  out.push(
    field(
      'plot.logY',
      'Logarithmic values',
      'For a term that spans decades (an NDF near a mirror).',
      logY,
      () => logY.checked || undefined,
    ),
  );
  return out;
}

/** The fields of shader exercise `raw`, each { path, box, read }. */
export function shaderFields(raw) {
  const slot = GRADED_SLOT_KEYS.includes(raw.slot) ? raw.slot : 'D';
  const family = GRADED_SLOTS[slot].family;
  const sources = textArea((raw.sources ?? []).join('\n'), 2);
  const slotSelect = select(Object.fromEntries(GRADED_SLOT_KEYS.map((k) => [k, SLOTS[k].signature])), slot);
  slotSelect.dataset.shape = 'slot';
  const starter = textArea(raw.starter, 8, { className: 'author-code', spellcheck: false });
  const term = select(termOptions(family), raw.reference?.term);
  term.dataset.shape = 'term';
  const rel = numberInput(raw.tolerance?.rel);
  const abs = numberInput(raw.tolerance?.abs);
  return [
    field(
      'sources',
      'Sources',
      'Where the formula comes from, one a line, each its authors and year (e.g. “Schlick 1994”).',
      sources,
      () => readLines(sources.value),
    ),
    field(
      'slot',
      'Function the student writes',
      'The GLSL function, in the talk’s conventions (n = (0, 0, 1)).',
      slotSelect,
      () => slot,
    ),
    field(
      'starter',
      'Starter code',
      'What the editor starts with (at most 8000 characters); it may be wrong on purpose. Never run here: the ' +
        'student’s GPU compiles it when they check.',
      starter,
      () => starter.value,
    ),
    field(
      'reference.term',
      'Graded against',
      `The catalogue’s ${family} term, evaluated in float64 at the same inputs.`,
      term,
      () => term.value,
    ),
    ...referenceParamFields(slot, raw.reference?.term, raw.reference?.params),
    ...Object.entries(GRADED_SLOTS[slot].axes).flatMap(([name, axis]) => axisFields(name, axis, raw.domain?.[name])),
    field(
      'tolerance.rel',
      'Tolerance, relative',
      'An input passes when |yours − reference| ≤ abs + rel·|reference| (0–1).',
      rel,
      () => readNumber(rel.value),
    ),
    field('tolerance.abs', 'Tolerance, absolute', 'The absolute part of the same test (0–1).', abs, () =>
      readNumber(abs.value),
    ),
    ...plotFields(raw),
  ];
}
