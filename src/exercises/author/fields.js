// The author form's fields: each a label, the control, what the field means, and a place for the validator's
// messages about it (data-field names the exercise field it writes, as the messages name it).
let next = 0;

export const el = (tag, props = {}, ...children) => {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
};

/**
 * A field's box. path: the exercise field it writes (e.g. "params.target"); label; meaning: one line on what it
 * is; control: an input, or a group of inputs (each with its own aria-label), which is then named by the label.
 */
export function fieldBox({ path, label, meaning, control }) {
  const id = `author-f${++next}`;
  const single = ['INPUT', 'SELECT', 'TEXTAREA'].includes(control.tagName);
  control.id ||= id;
  const help = el('p', { className: 'author-meaning', id: `${id}-help`, textContent: meaning });
  const errors = el('ul', { className: 'author-errors', id: `${id}-errors` });
  control.setAttribute('aria-describedby', `${help.id} ${errors.id}`);
  const title = el(single ? 'label' : 'span', { className: 'author-label', id: `${id}-label`, textContent: label });
  if (single) title.htmlFor = control.id;
  else {
    control.setAttribute('role', 'group');
    control.setAttribute('aria-labelledby', title.id);
  }
  const box = el('div', { className: 'author-field' }, title, control, help, errors);
  box.dataset.field = path;
  return box;
}

/** A field: its path, its box, and how to read its value (undefined: nothing to write). */
export const field = (path, label, meaning, control, read) => ({
  path,
  box: fieldBox({ path, label, meaning, control }),
  read,
  control,
});

/** A one-line text box. */
export const textInput = (value = '', props = {}) =>
  el('input', { type: 'text', value: value ?? '', autocomplete: 'off', spellcheck: false, ...props });

/** A number box: text, so that what was typed reaches the validator as typed. */
export const numberInput = (value) => textInput(value === undefined ? '' : String(value), { inputMode: 'decimal' });

export const textArea = (value = '', rows = 3, props = {}) => el('textarea', { value: value ?? '', rows, ...props });

/** A select of { key: words }; `none` adds a first option with the value '' (nothing chosen). */
export function select(options, value, none = null) {
  const s = el('select');
  if (none !== null) s.append(el('option', { value: '', textContent: none }));
  for (const [key, words] of Object.entries(options)) s.append(el('option', { value: key, textContent: words }));
  s.value = value ?? '';
  return s;
}

/** Shows `messages` in a field's box (or clears them), and marks its control invalid. */
export function showErrors(box, messages) {
  const list = box.querySelector(':scope > .author-errors');
  list.replaceChildren(...messages.map((m) => el('li', { textContent: m })));
  box.classList.toggle('has-errors', messages.length > 0);
  for (const c of box.querySelectorAll(':scope > input, :scope > select, :scope > textarea, :scope > .author-group'))
    c.setAttribute('aria-invalid', String(messages.length > 0));
}
