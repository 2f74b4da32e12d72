// One way to take a file from the user: dropped on a zone, or chosen in a file input (the keyboard's way in).
// Only drags that carry files light the zone up and are taken over: a dragged text or link keeps the browser's
// own behaviour (a number box inside the zone still takes a dropped number).

const carriesFiles = (e) => [...(e.dataTransfer?.types ?? [])].includes('Files');

/**
 * Calls `take(file)` with the first file dropped on `zone` or chosen in `options.input`; the zone has the class
 * `options.highlight` while files are dragged over it. Returns a function that removes every listener it added.
 * @param {HTMLElement} zone
 * @param {(file: File) => void} take
 * @param {{ input?: HTMLInputElement, highlight?: string }} [options]
 */
export function onFileDrop(zone, take, { input, highlight = 'dragging' } = {}) {
  const onDragOver = (e) => {
    if (!carriesFiles(e)) return;
    e.preventDefault(); // a drop target: without it the browser opens the file instead
    zone.classList.add(highlight);
  };
  const onDragLeave = () => zone.classList.remove(highlight);
  const onDrop = (e) => {
    const file = e.dataTransfer?.files?.[0];
    if (!file) return;
    e.preventDefault();
    zone.classList.remove(highlight);
    take(file);
  };
  const onChosen = () => input.files[0] && take(input.files[0]);
  zone.addEventListener('dragover', onDragOver);
  zone.addEventListener('dragleave', onDragLeave);
  zone.addEventListener('drop', onDrop);
  input?.addEventListener('change', onChosen);
  return () => {
    zone.removeEventListener('dragover', onDragOver);
    zone.removeEventListener('dragleave', onDragLeave);
    zone.removeEventListener('drop', onDrop);
    input?.removeEventListener('change', onChosen);
  };
}
