// A typed number answer, read by the rule the widget state uses (plain decimals: no hex, binary or Infinity),
// with a decimal comma taken as a point. NaN for anything else, so the page asks for a number.
import { parseNumber } from '../core/framework/state.js';

export const parseNumberAnswer = (raw) => parseNumber(raw.replace(',', '.'));
