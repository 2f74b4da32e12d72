// The controls a state exercise is answered with (its grader's `reads`), repeated in the answer form next to Check:
// on a phone the widget's own panel is a screen below its picture, and the question, the control that answers it
// and Check belong together. Each is a slider over the schema field's range with its value beside it; moving it
// updates the widget, and the widget's changes (its own panel, a drag on its picture) move it back.

const labelOf = (f, key) => `${f.label ?? key}${f.unit ? ` (${f.unit})` : ''}`;

/**
 * Sliders in `parent` for the number fields among `keys` of `schema` (locked ones left out), starting at `state`.
 * onInput(partial) after each move. Returns { sync(state) }.
 */
export function createAnswerControls(parent, { schema, keys, locked, state, onInput }) {
  const inputs = new Map();
  for (const key of keys) {
    const f = schema[key];
    if (f?.type !== 'number' || locked.includes(key)) continue;
    const id = `exercise-control-${key}`;
    const input = Object.assign(document.createElement('input'), {
      type: 'range',
      id,
      min: String(f.min),
      max: String(f.max),
      step: String(f.step ?? 'any'),
      value: String(state[key]),
    });
    const output = Object.assign(document.createElement('output'), { htmlFor: id, value: String(state[key]) });
    const label = Object.assign(document.createElement('label'), { htmlFor: id, textContent: labelOf(f, key) });
    input.addEventListener('input', () => {
      output.value = input.value;
      onInput({ [key]: Number(input.value) });
    });
    const row = document.createElement('div');
    row.className = 'exercise-control';
    row.append(label, input, output);
    parent.append(row);
    inputs.set(key, { input, output });
  }
  return {
    sync(next) {
      for (const [key, { input, output }] of inputs) {
        if (Number(input.value) === next[key]) continue;
        input.value = String(next[key]);
        output.value = String(next[key]);
      }
    },
  };
}
