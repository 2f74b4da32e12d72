// @ts-check
// The controls made from a user's slider lines (`uniform float name; // slider MIN MAX DEFAULT "Label"`): one range
// input per line, its value in the widget state's `params` record.

const STEPS = 200;

/**
 * @param {HTMLElement} container
 * @param {(name: string, value: number) => void} onInput
 */
export function createSliders(container, onInput) {
  const box = document.createElement('div');
  box.className = 'custom-sliders';
  container.append(box);
  let shownKey = '';

  /** @param {{ name: string, min: number, max: number, label: string }} p @param {number} value */
  function slider(p, value) {
    const label = document.createElement('label');
    const name = document.createElement('span');
    name.textContent = p.label || p.name;
    const input = Object.assign(document.createElement('input'), {
      type: 'range',
      min: String(p.min),
      max: String(p.max),
      step: String((p.max - p.min) / STEPS),
      value: String(value),
    });
    input.dataset.param = p.name;
    const out = document.createElement('output');
    out.textContent = value.toPrecision(3);
    input.addEventListener('input', () => {
      out.textContent = Number(input.value).toPrecision(3);
      onInput(p.name, Number(input.value));
    });
    label.append(name, input, out);
    return label;
  }

  return {
    /**
     * @param {{ name: string, min: number, max: number, label: string }[]} declared
     * @param {Record<string, number>} values  each declared name's value
     */
    show(declared, values) {
      const key = JSON.stringify([declared, values]);
      if (key === shownKey) return;
      shownKey = key;
      box.replaceChildren(...declared.map((p) => slider(p, values[p.name])));
      box.hidden = !declared.length;
    },
  };
}
