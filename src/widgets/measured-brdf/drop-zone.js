// The measured-BRDF widget's drop zone: a MERL file dropped on it or chosen in its file picker, and the words
// on the table shown.
import { onFileDrop } from '../../core/ui/file-drop.js';

/** A drop zone and a file picker; onFile(file) for either. */
export function createDropZone(container, onFile) {
  const zone = document.createElement('div');
  zone.className = 'measured-drop';
  zone.tabIndex = 0;
  const input = Object.assign(document.createElement('input'), { type: 'file', className: 'measured-file' });
  input.setAttribute('aria-label', 'Choose a MERL BRDF file');
  const text = document.createElement('p');
  text.innerHTML = 'Drop a MERL <code>.binary</code> file here (90 × 90 × 180, 35 MB), or choose one: ';
  text.append(input);
  const source = document.createElement('p');
  source.className = 'measured-source';
  zone.append(text, source);
  container.append(zone);
  const stopTaking = onFileDrop(zone, onFile, { input });
  return {
    setSource: (words) => (source.textContent = words),
    dispose() {
      stopTaking();
      zone.remove();
    },
  };
}
