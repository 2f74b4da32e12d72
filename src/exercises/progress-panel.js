// The exercises page's "Your progress as a file": save the progress on the set shown to a file, or load one saved
// before. In an LMS package the LMS keeps the progress and grades: loading a file there is refused, as it would
// send solved exercises to the gradebook that were not solved here.
import { download } from '../core/framework/download.js';
import { onFileDrop } from '../core/ui/file-drop.js';
import { progressFile, readProgressFile } from './progress.js';

/** state(): { exercises, progress, title }; onLoaded(): after a file was taken. lms: the LMS keeps the grades. */
export function createProgressPanel(doc, { state, onLoaded, lms }) {
  const message = doc.getElementById('progress-message');
  const say = (text, bad = false) => {
    message.textContent = text;
    message.className = bad ? 'notice notice-error' : '';
  };
  doc.getElementById('progress-save').addEventListener('click', () => {
    const { exercises, progress, title } = state();
    const name = /** @type {HTMLInputElement} */ (doc.getElementById('progress-name')).value;
    const file = progressFile({ name, title, exercises, progress });
    const stem = (name.replace(/[^\p{L}\p{N}]+/gu, '-').replace(/^-+|-+$/g, '') || 'my').toLowerCase();
    download(
      `${stem}-shading-lab-progress.json`,
      new Blob([JSON.stringify(file, null, 2)], { type: 'application/json' }),
    );
    say(`Saved: ${file.exercises.filter((e) => e.solved).length} of ${file.exercises.length} solved.`);
  });
  const take = async (blob) => {
    if (lms) return say('Your course’s LMS keeps your progress here: a progress file cannot be loaded into it.', true);
    const got = readProgressFile(await blob.text());
    if (got.error) return say(`${blob.name} ${got.error}; your progress is unchanged.`, true);
    const { exercises, progress } = state();
    const taken = progress.load(
      got.file.exercises,
      exercises.map((e) => e.id),
    );
    const left = got.file.exercises.length - taken;
    say(`Loaded ${taken} exercise${taken === 1 ? '' : 's'}${left ? ` (${left} not in this set left out)` : ''}.`);
    onLoaded();
  };
  onFileDrop(doc.getElementById('progress-drop'), take, { input: doc.getElementById('progress-load') });
}
