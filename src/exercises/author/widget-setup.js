// The widget of a widget exercise, mounted on the author page: the lecturer sets the starting state with the
// widget's own controls, and ticks the keys the student may not change. Nothing is locked here: the lecturer
// sets every value, the locks apply in the exercise.
import { mountOrExplain } from '../../core/framework/widget-failure.js';
import { unregisterWidget } from '../../core/framework/debug-hooks.js';
import { WIDGETS } from '../../widgets/registry.js';
import { compactState } from './draft.js';
import { el, fieldBox } from './fields.js';

/**
 * Mounts `name` in a new box with `state`, and a checkbox per state key (ticked: in `locked`). onChange() after
 * each change of the widget or of a lock. Returns { stateBox, lockBox, read() → { state, locked }, dispose }.
 */
export function createWidgetSetup({ name, state, locked, schemaOf, onChange }) {
  const slot = el('div', { className: 'author-widget' });
  const stateBox = fieldBox({
    path: 'state',
    label: `Starting state: ${WIDGETS[name].title}`,
    meaning:
      'Set up the question with the widget’s own controls: the exercise opens in this state. Only the values that ' +
      'differ from the widget’s defaults, and the locked ones, are saved.',
    control: slot,
  });
  const checks = el('div', { className: 'author-group author-locks' });
  const lockBox = fieldBox({
    path: 'locked',
    label: 'Fixed for the student (locked)',
    meaning: 'Ticked controls are shown to the student grey and framed, and cannot be changed.',
    control: checks,
  });
  let current = { ...state };
  let widget = null;
  let schema = null;
  let disposed = false;
  const lockedKeys = () => [...checks.querySelectorAll('input:checked')].map((c) => c.value);
  (async () => {
    schema = await schemaOf(name).catch(() => null);
    if (disposed || !schema) return;
    for (const [key, f] of Object.entries(schema)) {
      const box = el('input', { type: 'checkbox', value: key, checked: locked.includes(key) });
      box.addEventListener('change', onChange);
      checks.append(el('label', {}, box, ` ${f.label ?? key}`));
    }
    const mounted = await mountOrExplain(slot, name, {
      widgets: WIDGETS,
      prefix: 'author',
      syncUrl: false,
      state,
      onStateChange: (s) => {
        current = s;
        onChange();
      },
    });
    if (disposed) return mounted?.dispose();
    widget = mounted;
    if (widget) current = widget.getState();
  })();
  return {
    stateBox,
    lockBox,
    /** The exercise's state and locks: as given until the widget is up. */
    read() {
      if (!schema || !widget) return { state, locked };
      const keys = lockedKeys();
      return { state: compactState(schema, current, keys), locked: keys };
    },
    dispose() {
      disposed = true;
      widget?.dispose();
      unregisterWidget('author');
    },
  };
}
