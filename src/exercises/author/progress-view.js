// The lecturer's view of a student's progress file (saved on exercises.html with "Save my progress"): each
// exercise solved or not and in how many attempts, and the score the LMS would be given, weighed by points.
import { readProgressFile } from '../progress.js';
import { lessonStatus, scoreOf } from '../scorm/status.js';
import { el } from './fields.js';

/** file: as readProgressFile gives it; passMark: the set's (percent) or null. Returns the view's elements. */
export function progressView(file, passMark = null) {
  const ids = file.exercises.map((e) => e.id);
  const progress = Object.fromEntries(file.exercises.map((e) => [e.id, e]));
  const points = Object.fromEntries(file.exercises.map((e) => [e.id, e.points]));
  const score = scoreOf(ids, progress, points);
  const status = { passed: 'passed', failed: 'not passed', incomplete: 'not finished' }[lessonStatus(score, passMark)];
  const who = file.name || 'No name given';
  const when = file.saved ? `, saved ${new Date(file.saved).toLocaleString('en-GB')}` : '';
  const mark = passMark === null ? 'no pass mark: all solved to pass' : `pass mark ${passMark}%`;
  const row = (cells, tag = 'td') => el('tr', {}, ...cells.map((c) => el(tag, { textContent: String(c) })));
  const table = el(
    'table',
    { className: 'author-progress-table' },
    el('caption', { textContent: `${who}${file.set ? ` · ${file.set}` : ''}${when}` }),
    el('thead', {}, row(['Exercise', 'Solved', 'Attempts', 'Points'], 'th')),
    el('tbody', {}, ...file.exercises.map((e) => row([e.title, e.solved ? 'yes' : 'no', e.attempts, e.points]))),
  );
  const summary = el('p', {
    textContent:
      `Score ${score.raw}% (${score.solved} of ${score.total} solved; ${mark}): ${status}. ` +
      'The file is what the student’s browser recorded; it can be edited, so it is not proof.',
  });
  return [summary, table];
}

/** Reads a dropped or chosen file into the view; a bad file is said in words. */
export async function readStudentFile(blob, passMark) {
  const got = readProgressFile(await blob.text());
  return got.error
    ? [el('p', { className: 'notice notice-error', textContent: `${blob.name} ${got.error}.` })]
    : progressView(got.file, passMark);
}
