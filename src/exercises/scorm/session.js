// A session with a SCORM 1.2 LMS through its API object: every call checked (a throw, a "false", or a non-zero
// LMSGetLastError after a read), and each failure handed to `onProblem` in words, never dropped.
import { sessionTime } from './status.js';

const OK = new Set(['true', '0']); // SCORM 1.2 calls return the strings "true"/"false"; some LMSs return 0/1

/** api: the LMS's object; onProblem(text); now(): ms. Returns { start, save, finish }. */
export function createLmsSession(api, { onProblem, now = Date.now }) {
  const started = now();
  let open = false;
  const errorOf = () => {
    try {
      const code = String(api.LMSGetLastError());
      if (code === '0' || code === '') return null;
      const text = typeof api.LMSGetErrorString === 'function' ? String(api.LMSGetErrorString(code)) : '';
      return `error ${code}${text ? ` (${text})` : ''}`;
    } catch (e) {
      return `LMSGetLastError failed (${e.message})`;
    }
  };
  const call = (name, ...args) => {
    const what = `${name}(${args
      .map((a) => JSON.stringify(a))
      .join(', ')
      .slice(0, 60)})`;
    try {
      const result = api[name](...args);
      if (name === 'LMSGetValue' || name === 'LMSGetLastError') {
        const error = errorOf();
        if (error) onProblem(`The LMS refused ${what}: ${error}.`);
        return error ? null : String(result ?? '');
      }
      if (OK.has(String(result)) || result === true) return true;
      onProblem(`The LMS refused ${what}: ${errorOf() ?? `it returned ${JSON.stringify(result)}`}.`);
    } catch (e) {
      onProblem(`The LMS failed on ${what}: ${e.message}.`);
    }
    return null;
  };
  return {
    /** Initializes; returns { suspend, mastery } as the LMS gives them (strings; null if unreadable). */
    start() {
      open = Boolean(call('LMSInitialize', ''));
      return {
        suspend: call('LMSGetValue', 'cmi.suspend_data'),
        mastery: call('LMSGetValue', 'cmi.student_data.mastery_score'),
      };
    },
    /** Writes score, status, time and suspend data, then commits. */
    save({ raw, status, suspend }) {
      call('LMSSetValue', 'cmi.core.score.min', '0');
      call('LMSSetValue', 'cmi.core.score.max', '100');
      call('LMSSetValue', 'cmi.core.score.raw', String(raw));
      call('LMSSetValue', 'cmi.core.lesson_status', status);
      call('LMSSetValue', 'cmi.core.session_time', sessionTime(now() - started));
      call('LMSSetValue', 'cmi.suspend_data', suspend);
      // "suspend": the LMS keeps suspend_data, so a student who comes back sees what they solved
      call('LMSSetValue', 'cmi.core.exit', 'suspend');
      call('LMSCommit', '');
    },
    /** Once, on leaving the page. */
    finish() {
      if (!open) return;
      open = false;
      call('LMSSetValue', 'cmi.core.session_time', sessionTime(now() - started));
      call('LMSFinish', '');
    },
  };
}
