// Bringing your own environment: drop an .hdr or .exr file anywhere on the widget, or pick one with the
// button (the keyboard way). onFile(name, buffer) returns whether it was taken; the widget says why not.
// `accept` and `text`: other kinds of file the widget takes too (the material lab: a MERL table).
const TEXT = 'Load an .hdr / .exr environment…';
export function attachEnvironmentDrop(root, { onFile, maxBytes, accept = '.hdr,.exr', text = TEXT }) {
  const bar = document.createElement('div');
  bar.className = 'env-drop';
  const input = Object.assign(document.createElement('input'), {
    type: 'file',
    accept,
    className: 'visually-hidden',
    id: `env-file-${Math.random().toString(36).slice(2)}`,
  });
  const button = Object.assign(document.createElement('button'), { type: 'button', textContent: text });
  const status = Object.assign(document.createElement('span'), {
    className: 'env-drop-status',
    textContent: 'or drop one on the widget',
  });
  button.addEventListener('click', () => input.click());
  bar.append(button, input, status);
  root.querySelector('.widget-controls')?.append(bar);

  const take = async (file) => {
    if (!file) return;
    // a file over the limit is refused by its size alone, without reading it into memory
    const ok = onFile(file.name, file.size > maxBytes ? { byteLength: file.size } : await file.arrayBuffer());
    status.textContent = ok ? `Using ${file.name}` : 'or drop one on the widget';
  };
  const onDragOver = (e) => {
    if (![...(e.dataTransfer?.types ?? [])].includes('Files')) return;
    e.preventDefault();
    root.classList.add('drop-target');
  };
  const onDragLeave = () => root.classList.remove('drop-target');
  const onDrop = (e) => {
    if (!e.dataTransfer?.files?.length) return;
    e.preventDefault();
    root.classList.remove('drop-target');
    take(e.dataTransfer.files[0]);
  };
  const onInput = () => take(input.files[0]);
  root.addEventListener('dragover', onDragOver);
  root.addEventListener('dragleave', onDragLeave);
  root.addEventListener('drop', onDrop);
  input.addEventListener('change', onInput);
  return {
    dispose() {
      root.removeEventListener('dragover', onDragOver);
      root.removeEventListener('dragleave', onDragLeave);
      root.removeEventListener('drop', onDrop);
      bar.remove();
    },
  };
}
