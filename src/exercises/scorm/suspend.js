// A student's progress in cmi.suspend_data, which SCORM 1.2 caps at 4096 characters. Compact: the set's
// fingerprint, then one entry per exercise in the set's order ("" untried, "s3" solved in 3 attempts, "u2" not
// solved after 2), so 200 exercises (the most a set holds) take at most ~820 characters. Data from another set
// (another fingerprint) or not in this form is refused, never half-read.
export const SUSPEND_LIMIT = 4096;
export const MAX_ATTEMPTS = 36 ** 2 - 1; // two base-36 digits; more attempts are kept as this many
const PREFIX = 'SL1';

/** FNV-1a (32-bit) of the ids in order, in base 36: a change of set or of order changes it. */
export function setFingerprint(ids) {
  let h = 0x811c9dc5;
  for (const ch of ids.join('\n')) {
    h ^= ch.codePointAt(0);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h.toString(36);
}

/** progress: { [id]: { solved, attempts } } (src/exercises/progress.js). Returns the suspend_data string. */
export function encodeProgress(ids, progress) {
  const entries = ids.map((id) => {
    const p = Object.hasOwn(progress, id) ? progress[id] : null;
    const attempts = Math.min(MAX_ATTEMPTS, Math.max(0, Math.trunc(Number(p?.attempts) || 0)));
    if (!attempts && !p?.solved) return '';
    return `${p?.solved ? 's' : 'u'}${attempts.toString(36)}`;
  });
  return [PREFIX, setFingerprint(ids), entries.join('.')].join(':');
}

/**
 * The progress kept in `text` for this set: { progress, problem }. An empty text is a first visit (no problem);
 * a text from another set or unreadable gives { progress: {}, problem: 'foreign' | 'corrupt' }.
 */
export function decodeProgress(text, ids) {
  if (text === '' || text == null) return { progress: {}, problem: null };
  const parts = String(text).split(':');
  if (parts.length !== 3 || parts[0] !== PREFIX || !/^[0-9a-z]{1,7}$/.test(parts[1]))
    return { progress: {}, problem: 'corrupt' };
  if (parts[1] !== setFingerprint(ids)) return { progress: {}, problem: 'foreign' };
  const entries = parts[2].split('.');
  if (entries.length !== ids.length || !entries.every((e) => /^(|[su][0-9a-z]{1,2})$/.test(e)))
    return { progress: {}, problem: 'corrupt' };
  const progress = {};
  entries.forEach((e, i) => {
    if (e) progress[ids[i]] = { solved: e[0] === 's', attempts: parseInt(e.slice(1), 36) };
  });
  return { progress, problem: null };
}
