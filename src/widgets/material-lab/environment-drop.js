// Bringing your own environment: drop an .hdr or .exr file anywhere on the widget, or pick one with the
// button (the keyboard way). onFile(name, buffer) returns whether it was taken; the widget says why not.
// `accept` and `text`: other kinds of file the widget takes too (the material lab: a MERL table).
import { onFileDrop } from '../../core/ui/file-drop.js';

const TEXT = 'Load an .hdr / .exr environment…';
export function attachEnvironmentDrop(root, { onFile, maxBytes, accept = '.hdr,.exr', text = TEXT }) {
  const bar = document.createElement('div');
  bar.className = 'env-drop';
  const input = Object.assign(document.createElement('input'), {
    type: 'file',
    accept,
    className: 'visually-hidden',
    id: `env-file-${Math.random().toString(36).slice(2)}`,
    tabIndex: -1, // the button is the way in by keyboard: no stop on a control no one sees
  });
  input.setAttribute('aria-label', text); // named as the button that opens it
  const button = Object.assign(document.createElement('button'), { type: 'button', textContent: text });
  const status = Object.assign(document.createElement('span'), {
    className: 'env-drop-status',
    textContent: 'or drop one on the widget',
  });
  button.addEventListener('click', () => input.click());
  bar.append(button, input, status);
  root.querySelector('.widget-controls')?.append(bar);

  const take = async (file) => {
    // a file over the limit is refused by its size alone, without reading it into memory
    const ok = onFile(file.name, file.size > maxBytes ? { byteLength: file.size } : await file.arrayBuffer());
    status.textContent = ok ? `Using ${file.name}` : 'or drop one on the widget';
  };
  const stopTaking = onFileDrop(root, take, { input, highlight: 'drop-target' });
  return {
    dispose() {
      stopTaking();
      bar.remove();
    },
  };
}
