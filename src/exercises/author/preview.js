// The author page's preview: the exercise being edited in exercises.html itself, in a frame, so the lecturer
// answers it exactly as a student will (?preview=1: progress kept in memory, not in the lecturer's browser). The
// frame gets the exercise as a data: URL set, and only a version the validator passed.
import { el } from './fields.js';

const WAIT_MS = 600; // after the last keystroke: the frame reloads once a pause in typing says the edit is done

/** parent: where the frame goes. Returns { show(raw) (a valid exercise), stale(yes) (the one shown is older) }. */
export function createPreview(parent) {
  const note = el('p', { className: 'author-preview-note', role: 'status' });
  const frame = el('iframe', { title: 'Preview: the exercise as a student sees it', className: 'author-frame' });
  parent.append(note, frame);
  let timer = 0;
  let shown = '';
  note.textContent = 'Pick or add an exercise: it is shown here as a student sees it.';
  return {
    show(raw) {
      const text = JSON.stringify([raw]);
      clearTimeout(timer);
      if (text === shown) return;
      timer = setTimeout(() => {
        shown = text;
        const url = new URL('exercises.html', location.href);
        url.search = `preview=1&src=${encodeURIComponent(`data:application/json,${text}`)}`;
        url.hash = raw.id;
        frame.src = url.href;
        note.textContent = 'The exercise as a student sees it: answer it and press Check.';
      }, WAIT_MS);
    },
    stale() {
      clearTimeout(timer);
      note.textContent = shown
        ? 'The preview shows the last version without problems: fix those beside the fields.'
        : 'The preview appears once this exercise has no problems: each is said beside its field.';
    },
    clear() {
      clearTimeout(timer);
      shown = '';
      frame.removeAttribute('src');
      note.textContent = 'Pick or add an exercise: it is shown here as a student sees it.';
    },
  };
}
