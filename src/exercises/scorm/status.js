// What a SCORM 1.2 LMS is told about a set's progress: the score (percent of the set's points earned, 0–100, the
// scale of cmi.student_data.mastery_score) and the lesson status.

/**
 * progress: { [id]: { solved, attempts } }; points: { [id]: points } (1 for an id not in it). Returns
 * { solved, attempted, total, raw }: raw is the solved exercises' points as a percentage of all, to 0.01.
 */
export function scoreOf(ids, progress, points = {}) {
  const of = (id) => (Object.hasOwn(progress, id) ? progress[id] : null);
  const worth = (id) => (Object.hasOwn(points, id) ? points[id] : 1);
  const solved = ids.filter((id) => of(id)?.solved);
  const attempted = ids.filter((id) => of(id)?.solved || of(id)?.attempts > 0).length;
  const all = ids.reduce((sum, id) => sum + worth(id), 0);
  const earned = solved.reduce((sum, id) => sum + worth(id), 0);
  const raw = all ? Math.round((10000 * earned) / all) / 100 : 0;
  return { solved: solved.length, attempted, total: ids.length, raw };
}

/**
 * cmi.core.lesson_status. With a mastery score (the set's pass mark): passed once the score reaches it, failed
 * when every exercise was tried and it does not, incomplete before. Without: passed when all are solved.
 */
export function lessonStatus({ solved, attempted, total, raw }, mastery = null) {
  if (!total) return 'incomplete';
  if (mastery === null) return solved === total ? 'passed' : 'incomplete';
  if (raw >= mastery) return 'passed';
  return attempted === total ? 'failed' : 'incomplete';
}

/** A SCORM 1.2 CMITimeSpan, HHHH:MM:SS.SS (hours 2 to 4 digits, capped at 9999). */
export function sessionTime(ms) {
  const cs = Math.min(Math.max(0, Math.round(ms / 10)), 9999 * 360000 + 359999);
  const pad = (n, w) => String(n).padStart(w, '0');
  const h = Math.floor(cs / 360000);
  const m = Math.floor((cs % 360000) / 6000);
  const s = Math.floor((cs % 6000) / 100);
  return `${pad(h, 2)}:${pad(m, 2)}:${pad(s, 2)}.${pad(cs % 100, 2)}`;
}

/** The mastery score an LMS gives (cmi.student_data.mastery_score: "" when the package has none), or null. */
export function masteryOf(text) {
  const value = text === '' || text == null ? NaN : Number(text);
  return Number.isFinite(value) && value >= 0 && value <= 100 ? value : null;
}
