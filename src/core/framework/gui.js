// @ts-check
// Builds a lil-gui panel from a state schema. The panel edits a private copy of the state and reports
// each change as a partial state; sync() refreshes it when the state changes from elsewhere.
import GUI from 'lil-gui';

/** @typedef {import('./types.js').Field} Field */

/** @param {import('lil-gui').Controller} ctrl */
const lock = (ctrl) => {
  ctrl.disable();
  ctrl.domElement.classList.add('locked');
  ctrl.domElement.title = 'Fixed by the exercise';
};

/** @type {(key: string, f: Field) => string} */
const labelOf = (key, f) => (f.unit ? `${f.label ?? key} (${f.unit})` : (f.label ?? key));

/**
 * `locked`: keys shown but not editable (an exercise fixes them); their controls are disabled.
 * @param {HTMLElement} container
 * @param {object} spec
 * @param {import('./types.js').Schema} spec.schema
 * @param {import('./types.js').State} spec.state
 * @param {(partial: Partial<import('./types.js').State>) => void} spec.onChange
 * @param {string} [spec.title]
 * @param {string[]} [spec.keys]
 * @param {string[]} [spec.locked]
 */
export function createStateGui(
  container,
  { schema, state, onChange, title = 'Controls', keys = Object.keys(schema), locked = [] },
) {
  const gui = new GUI({ container, title, autoPlace: false });
  const model = { ...state };
  /** @type {Record<string, Record<string, boolean>>} */
  const setModels = {}; // set fields: one boolean per option
  /** @type {Map<string, GUI>} */
  const groups = new Map(); // a field's `group` puts it in a folder of that name (long panels stay readable)
  /** @type {Map<string, import('lil-gui').Controller[]>} */
  const controllersOf = new Map(); // a key's controllers: sync refreshes only those whose value changed
  /** @type {(key: string, ctrl: import('lil-gui').Controller) => void} */
  const keep = (key, ctrl) => {
    controllersOf.set(key, [...(controllersOf.get(key) ?? []), ctrl]);
  };
  /** @type {(f: Field) => GUI} */
  const parentOf = (f) => {
    if (!f.group) return gui;
    if (!groups.has(f.group)) groups.set(f.group, f.closed ? gui.addFolder(f.group).close() : gui.addFolder(f.group));
    return /** @type {GUI} */ (groups.get(f.group));
  };

  for (const key of keys) {
    const f = schema[key];
    // data handed over by another widget, or edited by a panel of its own (a user-written term's code and sliders)
    if (['samples', 'text', 'code', 'params'].includes(f.type)) continue;
    const parent = parentOf(f);
    if (f.type === 'set') {
      const folder = parent.addFolder(labelOf(key, f));
      /** @type {Record<string, boolean>} */
      const flags = (setModels[key] = {});
      const chosen = /** @type {string[]} */ (model[key]);
      for (const [value, label] of Object.entries(f.options)) {
        flags[value] = chosen.includes(value);
        const ctrl = folder
          .add(flags, value)
          .name(label)
          .onChange(() => {
            onChange({ [key]: Object.keys(f.options).filter((v) => flags[v]) });
          });
        if (locked.includes(key)) lock(ctrl);
        keep(key, ctrl);
      }
      continue;
    }
    const ctrl =
      f.type === 'number'
        ? parent.add(model, key, f.min, f.max, f.step)
        : f.type === 'enum'
          ? parent.add(model, key, Object.fromEntries(Object.entries(f.options).map(([v, l]) => [l, v])))
          : f.type === 'color'
            ? parent.addColor(model, key)
            : parent.add(model, key);
    ctrl.name(labelOf(key, f)).onChange((/** @type {import('./types.js').StateValue} */ v) => onChange({ [key]: v }));
    if (f.hint) ctrl.domElement.title = f.hint;
    if (locked.includes(key)) lock(ctrl);
    keep(key, ctrl);
  }

  /**
   * Brings the panel's copy of `key` to `value`; false when it already shows it (the control that made the change).
   * @param {string} key
   * @param {import('./types.js').StateValue} value
   */
  const take = (key, value) => {
    const flags = setModels[key];
    if (flags) {
      const chosen = /** @type {string[]} */ (value);
      const stale = Object.keys(flags).filter((v) => flags[v] !== chosen.includes(v));
      stale.forEach((v) => (flags[v] = !flags[v]));
      return stale.length > 0;
    }
    const stale = JSON.stringify(model[key]) !== JSON.stringify(value);
    model[key] = value;
    return stale;
  };

  return {
    gui,
    /** @param {import('./types.js').State} next */
    sync(next) {
      for (const [key, ctrls] of controllersOf) if (take(key, next[key])) ctrls.forEach((c) => c.updateDisplay());
      Object.assign(model, next);
    },
    dispose() {
      gui.destroy();
    },
  };
}
