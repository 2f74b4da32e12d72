// @ts-check
// The formula each widget evaluates, declared in its words.js as a function of its state: TeX in the talk's
// notation with the current values substituted, and `\sym{key}{…}` around each symbol a control sets (`key` is
// the state key), which ties the symbol to that control (live-formula.js). Pure: no DOM, loads in Node.

/** @typedef {(state: import('./types.js').State) => string} FormulaOf  state → TeX */

/** @type {Map<string, FormulaOf>} */
const DECLARED = new Map();

/**
 * Declares widget `name`'s live formula; its shell (widget-shell.js) finds it by the name and shows it.
 * @param {string} name
 * @param {FormulaOf} texOf
 * @returns {FormulaOf}
 */
export function declareFormula(name, texOf) {
  DECLARED.set(name, texOf);
  return texOf;
}

/**
 * The live formula declared for widget `name`, if any.
 * @param {string} name
 * @returns {FormulaOf | undefined}
 */
export const declaredFormula = (name) => DECLARED.get(name);

/** The talk's dot products as TeX macros, for every formula of the app: \nl is (n·l) with bold vectors, etc. */
export const TALK_MACROS = Object.fromEntries(
  ['nl', 'nv', 'nh', 'nm', 'nx', 'lh', 'vh'].map((ab) => [`\\${ab}`, `(\\mathbf{${ab[0]}}\\cdot\\mathbf{${ab[1]}})`]),
);

/** The TeX macros of a live formula: the talk's, and \sym{key}{body} marking a symbol (KaTeX keeps only an href
 * in MathML). */
export const FORMULA_MACROS = { ...TALK_MACROS, '\\sym': '\\href{\\#sym:#1}{#2}' };

/**
 * A number as TeX, `digits` after the point; exponents as ×10^n for very small or large magnitudes.
 * @param {number} x
 * @param {number} [digits]
 */
export function texNumber(x, digits = 3) {
  if (!Number.isFinite(x)) return '\\text{—}';
  const a = Math.abs(x);
  if (a !== 0 && (a < 10 ** -digits || a >= 1e5)) {
    const [m, e] = x.toExponential(2).split('e');
    return `${m} \\times 10^{${Number(e)}}`;
  }
  return x.toFixed(digits);
}

/**
 * Plain words inside a formula (a material's or a model's name), with TeX's special characters escaped.
 * @param {string} s
 */
export const texText = (s) => `\\text{${s.replace(/[\\^~]/g, '').replace(/[{}$&#_%]/g, (c) => `\\${c}`)}}`;

/**
 * A number as TeX to `digits` significant digits (a coefficient spanning decades: 0.0366, 60, 3780).
 * @param {number} x
 * @param {number} [digits]
 */
export function texSignificant(x, digits = 3) {
  if (!Number.isFinite(x)) return '\\text{—}';
  const a = Math.abs(x);
  if (a !== 0 && (a < 1e-4 || a >= 1e6)) return texNumber(x);
  return String(Number(x.toPrecision(digits)));
}

/**
 * A term the user wrote in GLSL, as every live formula names it: `symbol` with the subscript "yours", over its
 * arguments (TeX).
 * @param {string} symbol
 * @param {string} args
 */
export const texYoursTerm = (symbol, args) => `${symbol}_{\\text{yours}}(${args})`;

/** What a formula says of the terms it names with texYoursTerm. */
export const TEX_YOURS_NOTE = '\\ \\text{(your GLSL, evaluated on the GPU)}';

/**
 * One user-written term with the note: texYoursTerm, then `where` (TeX, e.g. "α = σ in radians"), then the note.
 * @param {string} symbol
 * @param {string} args
 * @param {string} [where]
 */
export const texYours = (symbol, args, where = '') =>
  `${texYoursTerm(symbol, args)}${where ? `,\\ ${where}` : ''}${TEX_YOURS_NOTE}`;
