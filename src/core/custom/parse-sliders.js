// @ts-check
// A user-written term's slider lines, read line by line before the code is parsed: each `uniform` line must be
// `uniform float name; // slider MIN MAX DEFAULT "Label"` and becomes a parameter; preprocessor lines are refused.
import { DECIMAL, MAX_PARAMS } from './code-state.js';

const MAX_LABEL = 40;

/** @typedef {{ name: string, min: number, max: number, value: number, label: string, line: number }} Param */
/** @typedef {{ line: number, message: string }} Problem */

const SLIDER =
  /^\s*uniform\s+float\s+([A-Za-z_]\w*)\s*;\s*\/\/\s*slider\s+(\S+)\s+(\S+)\s+(\S+)\s+"([^"\p{Cc}]*)"\s*$/u;
export const SLIDER_FORM = 'uniform float name; // slider MIN MAX DEFAULT "Label"';
export const UNIFORM_LINE = /^\s*uniform\b/;

/**
 * The slider of one `uniform` line, or a problem.
 * @param {string} text
 * @param {number} line
 * @returns {{ param: Param } | { problem: Problem }}
 */
function sliderOf(text, line) {
  const m = SLIDER.exec(text);
  if (!m) return { problem: { line, message: `a uniform must be a slider line: ${SLIDER_FORM}` } };
  const [, name, ...rest] = m;
  const label = rest[3].trim();
  const [min, max, value] = rest.slice(0, 3).map((s) => (DECIMAL.test(s) ? Number(s) : NaN));
  const bad = (/** @type {string} */ why) => ({ problem: { line, message: `slider '${name}': ${why}` } });
  if (![min, max, value].every(Number.isFinite)) return bad(`MIN MAX DEFAULT must be decimal numbers (${SLIDER_FORM})`);
  if (!(min < max)) return bad(`MIN (${min}) must be below MAX (${max})`);
  if (!(value >= min && value <= max)) return bad(`DEFAULT ${value} is outside ${min}…${max}`);
  if (!label || label.length > MAX_LABEL) return bad(`the label must have 1 to ${MAX_LABEL} characters`);
  return { param: { name, min, max, value, label, line } };
}

/**
 * Sliders and line-level refusals (preprocessor directives, uniforms that are no slider).
 * @param {string[]} lines
 */
export function scanLines(lines) {
  /** @type {Param[]} */
  const params = [];
  /** @type {Problem[]} */
  const problems = [];
  lines.forEach((text, i) => {
    const line = i + 1;
    if (/^\s*#/.test(text)) problems.push({ line, message: 'preprocessor directives (#…) are not available here' });
    if (!UNIFORM_LINE.test(text)) return;
    const found = sliderOf(text, line);
    if ('problem' in found) problems.push(found.problem);
    else if (params.some((p) => p.name === found.param.name))
      problems.push({ line, message: `slider '${found.param.name}' is declared twice` });
    else if (params.length === MAX_PARAMS) problems.push({ line, message: `at most ${MAX_PARAMS} sliders` });
    else params.push(found.param);
  });
  return { params, problems };
}
