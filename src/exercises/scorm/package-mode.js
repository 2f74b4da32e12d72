// Package mode of exercises.html (?scorm=1, as a SCORM package's launch page opens it): progress goes to the
// LMS (score, status, suspend data) through a Storage-like object that src/exercises/progress.js writes to.
// Without an LMS the page keeps its progress in the browser as always, and says grades are not recorded.
import { findLmsApi } from './api.js';
import { createLmsSession } from './session.js';
import { decodeProgress, encodeProgress } from './suspend.js';
import { lessonStatus, masteryOf, scoreOf } from './status.js';
import { memoryStorage } from '../progress.js';

const NO_LMS =
  'Package mode, but no learning management system (LMS) was found: your answers are checked here, and your ' +
  'progress stays in this browser, but grades are not being recorded.';
const CONNECTED = 'Connected to your course’s LMS: each checked answer is sent to its gradebook.';
const NOT_SENT = 'The exercises you loaded yourself are checked here, but not sent to the LMS.';
const AFRESH = {
  foreign: 'The progress your LMS kept for this package belongs to another exercise set, so you start afresh.',
  corrupt: 'The progress your LMS kept for this package could not be read, so you start afresh.',
};

/**
 * Shows the mode's notices in a box put before `place`. Returns { storageFor(ids, { points, passMark }) } for
 * createProgress: points per id, and the set's pass mark for an LMS that gives no mastery score.
 */
export function startPackageMode({ win = window, place }) {
  const box = Object.assign(win.document.createElement('div'), { className: 'notice scorm-notice' });
  box.setAttribute('role', 'status');
  place.before(box);
  const say = (text, kind = '') => {
    const p = Object.assign(win.document.createElement('p'), { textContent: text, className: kind });
    box.append(p);
    if (kind) box.classList.add('notice-error');
  };
  const api = findLmsApi(win);
  if (!api) {
    say(NO_LMS);
    return { lms: false, storageFor: () => win.localStorage };
  }
  say(CONNECTED);
  const session = createLmsSession(api, {
    onProblem: (text) => say(`${text} Your answers are still checked here.`, 'scorm-problem'),
  });
  const { suspend, mastery: masteryText } = session.start();
  const mastery = masteryOf(masteryText);
  win.addEventListener('pagehide', () => session.finish());
  let restored = false;
  return {
    lms: true,
    storageFor(ids, { points = {}, passMark = null } = {}) {
      if (!ids.length) return memoryStorage(); // a set that failed to load must not overwrite the kept progress
      if (restored) {
        say(NOT_SENT); // a set the student loads is theirs: kept in memory, never sent over the package's grades
        return memoryStorage();
      }
      restored = true; // only the set the package opened with goes to the LMS
      const got = decodeProgress(suspend ?? '', ids);
      if (got.problem) say(AFRESH[got.problem], 'scorm-problem');
      let progress = got.progress;
      const save = () => {
        const score = scoreOf(ids, progress, points);
        const status = lessonStatus(score, mastery ?? passMark);
        session.save({ raw: score.raw, status, suspend: encodeProgress(ids, progress) });
      };
      save();
      return {
        getItem: () => JSON.stringify(progress),
        setItem: (_key, json) => {
          progress = JSON.parse(json);
          save();
        },
        removeItem: () => {
          progress = {};
          save();
        },
      };
    },
  };
}
