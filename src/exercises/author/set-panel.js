// The set being built on the author page: its title and pass mark (with the validator's messages beside them),
// and its exercises in order, each with its title, points and problems, to pick for editing, move or remove.
import { readNumber } from './draft.js';
import { el, field, numberInput, showErrors, textInput } from './fields.js';

/** parent: where the panel goes; on: { select(i), move(i, by), remove(i), change() } (title or pass mark). */
export function createSetPanel(parent, on) {
  const title = textInput('');
  const passMark = numberInput(undefined);
  const head = [
    field(
      'title',
      'Set title',
      'Shown by an LMS as the package’s name (optional).',
      title,
      () => title.value.trim() || undefined,
    ),
    field(
      'passMark',
      'Pass mark (%)',
      'The share of the points to pass, 0–100; an LMS gets it as the mastery score (optional).',
      passMark,
      () => readNumber(passMark.value),
    ),
  ];
  for (const f of head) f.control.addEventListener('input', on.change);
  const others = el('ul', { className: 'author-errors' }); // the set's messages that name neither field
  const list = el('ol', { className: 'author-items' });
  const empty = el('p', {
    className: 'author-empty',
    textContent: 'No exercises yet: add a built-in one or a new one.',
  });
  parent.append(...head.map((f) => f.box), others, empty, list);

  const button = (text, label, act) => {
    const b = el('button', { type: 'button', textContent: text, onclick: act });
    if (label) b.setAttribute('aria-label', label);
    return b;
  };

  return {
    /** { title, passMark } as typed (undefined when empty). */
    read: () => Object.fromEntries(head.map((f) => [f.path, f.read()])),
    /** Sets the title and pass mark fields (an opened set's). */
    fill({ title: t, passMark: p }) {
      title.value = t ?? '';
      passMark.value = p === undefined || p === null ? '' : String(p);
    },
    /** items: [{ raw, errors }]; selected: the index edited; setErrors: the set's own messages. */
    render(items, selected, setErrors) {
      empty.hidden = items.length > 0;
      const mine = (f) => (e) => e.startsWith(`${f.path}: `);
      for (const f of head) showErrors(f.box, setErrors.filter(mine(f)));
      const rest = setErrors.filter((e) => !head.some((f) => mine(f)(e)));
      others.replaceChildren(...rest.map((e) => el('li', { textContent: e })));
      list.replaceChildren(
        ...items.map(({ raw, errors }, i) => {
          const name = raw.title || raw.id || `exercise ${i + 1}`;
          const pick = button(name, null, () => on.select(i));
          pick.className = 'author-pick';
          if (i === selected) pick.setAttribute('aria-current', 'true');
          const points = raw.points ?? 1;
          const status = errors.length ? `${errors.length} problem${errors.length > 1 ? 's' : ''}` : 'ready';
          const meta = el('span', {
            className: `author-item-meta${errors.length ? ' bad' : ''}`,
            textContent: ` ${points} point${points === 1 ? '' : 's'} · ${status}`,
          });
          const up = button('Up', `Up: move “${name}” up`, () => on.move(i, -1));
          const down = button('Down', `Down: move “${name}” down`, () => on.move(i, 1));
          up.disabled = i === 0;
          down.disabled = i === items.length - 1;
          const remove = button('Remove', `Remove “${name}”`, () => on.remove(i)); // the visible word first
          return el('li', {}, pick, meta, el('span', { className: 'author-item-tools' }, up, down, remove));
        }),
      );
    },
  };
}
