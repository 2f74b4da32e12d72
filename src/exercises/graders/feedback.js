// Numbers and verdicts as every grader's feedback writes them.

/** A number for feedback: 3 significant digits, no exponent for everyday sizes. */
export const fmt = (x, digits = 3) => {
  if (!Number.isFinite(x)) return String(x);
  const a = Math.abs(x);
  if (a !== 0 && (a < 1e-3 || a >= 1e5)) return x.toExponential(digits - 1);
  return String(Number(x.toPrecision(digits)));
};

export const pct = (x) => `${fmt(x * 100)}%`;

export const times = (r) => `${fmt(r, 2)}×`;

/** "x is too low by d (r%)" for a number answer against its target. */
export function offBy(answer, target, unit) {
  const d = answer - target;
  const rel = target !== 0 ? ` (${d > 0 ? '+' : '−'}${pct(Math.abs(d / target))})` : '';
  return `${fmt(answer)}${unit} is too ${d > 0 ? 'high' : 'low'} by ${fmt(Math.abs(d))}${unit}${rel}`;
}
