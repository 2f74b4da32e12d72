// The SCORM 1.2 core of package mode, in Node: suspend data within SCORM 1.2's 4096 characters (CMIString4096),
// the score and lesson status, the CMITimeSpan format, the RTE's API search and a session's error reporting.
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { MAX_SET_ENTRIES } from '../../src/exercises/load.js';
import { MAX_ATTEMPTS, SUSPEND_LIMIT, decodeProgress, encodeProgress } from '../../src/exercises/scorm/suspend.js';
import { lessonStatus, masteryOf, scoreOf, sessionTime } from '../../src/exercises/scorm/status.js';
import { findLmsApi } from '../../src/exercises/scorm/api.js';
import { createLmsSession } from '../../src/exercises/scorm/session.js';

const DIR = join(import.meta.dirname, '../../public/exercises');
const BUILT_IN = JSON.parse(readFileSync(join(DIR, 'index.json'), 'utf8')).exercises.map(
  (f) => JSON.parse(readFileSync(join(DIR, f), 'utf8')).id,
);
const worst = (ids) => Object.fromEntries(ids.map((id) => [id, { solved: false, attempts: 10 ** 6 }]));

describe('suspend data', () => {
  it('round-trips the built-in set’s progress, solved, unsolved and untried', () => {
    const progress = {
      [BUILT_IN[0]]: { solved: true, attempts: 3 },
      [BUILT_IN[4]]: { solved: false, attempts: 2 },
      [BUILT_IN[18]]: { solved: true, attempts: 1 },
    };
    const text = encodeProgress(BUILT_IN, progress);
    expect(decodeProgress(text, BUILT_IN)).toEqual({ progress, problem: null });
  });

  it('stays within SCORM 1.2’s 4096 characters: the built-in set and a 200-exercise set with long ids', () => {
    expect(SUSPEND_LIMIT).toBe(4096);
    const builtIn = encodeProgress(BUILT_IN, worst(BUILT_IN));
    expect(builtIn.length).toBeLessThanOrEqual(5 * BUILT_IN.length); // per exercise "u" + 2 digits + "." and a little
    const ids = Array.from({ length: MAX_SET_ENTRIES }, (_, i) => `an-exercise-with-a-rather-long-id-${i}`);
    const big = encodeProgress(ids, worst(ids));
    expect(big.length).toBeLessThanOrEqual(SUSPEND_LIMIT);
    expect(decodeProgress(big, ids).progress[ids[7]]).toEqual({ solved: false, attempts: MAX_ATTEMPTS });
  });

  it('refuses another set’s data (other ids or order) and corrupt text, keeping nothing of it', () => {
    const text = encodeProgress(BUILT_IN, { [BUILT_IN[0]]: { solved: true, attempts: 1 } });
    expect(decodeProgress(text, [...BUILT_IN].reverse())).toEqual({ progress: {}, problem: 'foreign' });
    for (const bad of ['{"a":1}', 'SL1:x', text.replace(/s1/, 'z9'), `${text}.`, 'SL1::'])
      expect(decodeProgress(bad, BUILT_IN)).toEqual({ progress: {}, problem: 'corrupt' });
    expect(decodeProgress('', BUILT_IN)).toEqual({ progress: {}, problem: null });
  });
});

describe('score and status', () => {
  const ids = ['a', 'b', 'c', 'd'];
  it('scores the percentage solved and reports passed/failed/incomplete against a mastery score', () => {
    const p = { a: { solved: true, attempts: 1 }, b: { solved: false, attempts: 2 }, c: { solved: true, attempts: 4 } };
    const s = scoreOf(ids, p);
    expect(s).toEqual({ solved: 2, attempted: 3, total: 4, raw: 50 });
    expect(lessonStatus(s)).toBe('incomplete');
    expect(lessonStatus(s, 50)).toBe('passed');
    expect(lessonStatus(s, 75)).toBe('incomplete');
    expect(lessonStatus(scoreOf(ids, { ...p, d: { solved: false, attempts: 1 } }), 75)).toBe('failed');
    expect(lessonStatus(scoreOf(ids, { ...p, b: { solved: true }, d: { solved: true } }))).toBe('passed');
    expect(scoreOf(['a', 'b', 'c'], { a: { solved: true } }).raw).toBe(33.33);
  });
  it('reads an LMS’s mastery score ("" means none)', () => {
    expect([masteryOf(''), masteryOf('80'), masteryOf('x'), masteryOf('120')]).toEqual([null, 80, null, null]);
  });
  it('writes session time as CMITimeSpan HHHH:MM:SS.SS (1 h 2 min 3.45 s)', () => {
    expect(sessionTime(3723450)).toBe('01:02:03.45');
    expect(sessionTime(0)).toBe('00:00:00.00');
    expect(sessionTime(1e12)).toBe('9999:59:59.99');
  });
});

const fakeApi = (overrides = {}) => {
  const calls = [];
  const store = { 'cmi.suspend_data': '', 'cmi.student_data.mastery_score': '' };
  const api = {
    calls,
    store,
    error: '0',
    LMSInitialize: () => 'true',
    LMSFinish: () => 'true',
    LMSCommit: () => (calls.push(['commit']), 'true'),
    LMSGetValue: (k) => store[k] ?? '',
    LMSSetValue: (k, v) => (calls.push([k, v]), (store[k] = v), 'true'),
    LMSGetLastError: () => api.error,
    LMSGetErrorString: (c) => `text of ${c}`,
    ...overrides,
  };
  return api;
};

describe('finding the API (SCORM 1.2 RTE: this window, up to 7 parents, then the opener)', () => {
  const chain = (n, api) => {
    let top = { API: api };
    top.parent = top;
    let win = top;
    for (let i = 0; i < n; i++) win = { parent: win };
    return win;
  };
  it('finds it 7 parents up, not 8, and on the opener', () => {
    const api = fakeApi();
    expect(findLmsApi(chain(7, api))).toBe(api);
    expect(findLmsApi(chain(8, api))).toBe(null);
    const win = { parent: null, opener: chain(2, api) };
    win.parent = win;
    expect(findLmsApi(win)).toBe(api);
  });
  it('stops at a parent it may not read, and ignores an API without the LMS calls', () => {
    const blocked = {};
    Object.defineProperty(blocked, 'API', {
      get: () => {
        throw new Error('SecurityError');
      },
    });
    blocked.parent = blocked;
    expect(findLmsApi({ parent: blocked })).toBe(null);
    expect(findLmsApi(chain(1, { LMSInitialize() {} }))).toBe(null);
  });
});

describe('an LMS session', () => {
  it('writes score, status, time and suspend data, then commits', () => {
    const api = fakeApi();
    let t = 1000;
    const s = createLmsSession(api, {
      onProblem: (m) => {
        throw new Error(m);
      },
      now: () => t,
    });
    expect(s.start()).toEqual({ suspend: '', mastery: '' });
    t += 61_500;
    s.save({ raw: 50, status: 'incomplete', suspend: 'SL1:x:s1' });
    expect(api.store).toMatchObject({
      'cmi.core.score.raw': '50',
      'cmi.core.score.max': '100',
      'cmi.core.lesson_status': 'incomplete',
      'cmi.core.session_time': '00:01:01.50',
      'cmi.suspend_data': 'SL1:x:s1',
    });
    expect(api.calls.at(-1)).toEqual(['commit']);
  });
  it('reports a refused call with LMSGetLastError’s code and text, and a throwing call by its message', () => {
    const problems = [];
    const api = fakeApi({
      LMSSetValue: () => ((api.error = '405'), 'false'),
      LMSCommit: () => {
        throw new Error('gone');
      },
    });
    const s = createLmsSession(api, { onProblem: (m) => problems.push(m) });
    s.start();
    s.save({ raw: 0, status: 'incomplete', suspend: '' });
    expect(problems[0]).toMatch(/refused LMSSetValue\("cmi.core.score.min", "0"\): error 405 \(text of 405\)/);
    expect(problems.at(-1)).toBe('The LMS failed on LMSCommit(""): gone.');
  });
});
