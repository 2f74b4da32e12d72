// @ts-check
// Text with formulas in it, from data (tour steps, exercise prompts): `$…$` spans are TeX in the talk's notation
// (TALK_MACROS), `\$` is a literal dollar, a lone `$` stays as it is. A formula becomes a data-tex span whose text
// is a plain fallback derived from its TeX (what a reader sees until KaTeX has run, and what tests read); the rest
// stays text nodes. Nothing is ever parsed as HTML: exercise files come from any URL.

import { TALK_MACROS } from '../framework/formula-registry.js';

/** @typedef {{ text: string } | { tex: string, plain: string }} InlinePart */

/**
 * Splits `source` into text and TeX parts; `\$` outside a formula is a dollar sign.
 * @param {string} source
 * @returns {InlinePart[]}
 */
export function parseInlineTex(source) {
  /** @type {InlinePart[]} */
  const parts = [];
  let text = '';
  for (let i = 0; i < source.length; i++) {
    if (source.startsWith('\\$', i)) {
      text += '$';
      i++;
      continue;
    }
    const end = source[i] === '$' ? closingDollar(source, i + 1) : -1;
    if (end < 0) {
      text += source[i];
      continue;
    }
    if (text) parts.push({ text });
    text = '';
    const tex = source.slice(i + 1, end);
    parts.push({ tex, plain: texToPlain(tex) });
    i = end;
  }
  if (text) parts.push({ text });
  return parts;
}

/** The index of the `$` that closes a formula opened before `from` (skipping TeX escapes), or -1. */
function closingDollar(/** @type {string} */ source, /** @type {number} */ from) {
  for (let j = from; j < source.length; j++) {
    if (source[j] === '\\') j++;
    else if (source[j] === '$') return j > from ? j : -1;
  }
  return -1;
}

/** Text with its formulas read as their plain fallback: what a reader sees before (or without) KaTeX. */
export const inlineTexPlain = (/** @type {string} */ source) =>
  parseInlineTex(source)
    .map((p) => ('text' in p ? p.text : p.plain))
    .join('');

/** @type {Record<string, string>} */
const SYMBOLS = {
  alpha: 'α',
  beta: 'β',
  gamma: 'γ',
  eta: 'η',
  theta: 'θ',
  pi: 'π',
  sigma: 'σ',
  mu: 'μ',
  lambda: 'λ',
  omega: 'ω',
  Omega: 'Ω',
  cdot: '·',
  times: '×',
  approx: '≈',
  le: '≤',
  leq: '≤',
  ge: '≥',
  geq: '≥',
  to: '→',
  infty: '∞',
  otimes: '⊗',
  circ: '°',
  pm: '±',
  ldots: '…',
  '%': '%',
  $: '$',
  '{': '{',
  '}': '}',
  ',': ' ',
  ';': ' ',
  quad: '  ',
};
/** @type {Record<string, string>} */
const SUPERSCRIPT = {
  '°': '°',
  0: '⁰',
  1: '¹',
  2: '²',
  3: '³',
  4: '⁴',
  5: '⁵',
  6: '⁶',
  7: '⁷',
  8: '⁸',
  9: '⁹',
  '−': '⁻',
};
/** Macros whose argument is read as it is (`\mathbf{n}` → n). */
const KEEP_ARGUMENT = new Set(['mathbf', 'mathrm', 'text', 'operatorname', 'boldsymbol', 'mathit']);

/** Whether x is one bracket pair: its first `(` closes at its end. */
function bracketed(/** @type {string} */ x) {
  let depth = 0;
  for (let k = 0; k < x.length; k++) {
    depth += x[k] === '(' ? 1 : x[k] === ')' ? -1 : 0;
    if (depth === 0) return k === x.length - 1 && k > 0;
  }
  return false;
}
/** `(x)` unless x is one symbol or number, or already bracketed. */
const group = (/** @type {string} */ x) => (/^[\p{L}\p{N}.·′_]+$/u.test(x) || bracketed(x) ? x : `(${x})`);

/**
 * The readable plain form of a formula: the talk's macros written out, Greek letters and operators as Unicode,
 * fractions as a/b, roots as √, small powers as superscripts, braces and sizing commands dropped.
 * @param {string} tex
 */
export function texToPlain(tex) {
  const src = Object.entries(TALK_MACROS).reduce(
    (s, [name]) => s.replace(new RegExp(`\\${name}(?![A-Za-z])`, 'g'), `(${name[1]}·${name[2]})`),
    tex,
  );
  let i = 0;
  /** One argument: a {group} or a single character or command. @returns {string} */
  const argument = () => {
    while (src[i] === ' ') i++;
    if (src[i] !== '{') return atom();
    i++;
    return sequence('}');
  };
  /** @returns {string} */
  const atom = () => {
    const c = src[i++] ?? '';
    if (c === '{') return sequence('}');
    if (c !== '\\') return c === '-' ? '−' : c;
    const name = /^[A-Za-z]+/.exec(src.slice(i))?.[0] ?? src[i] ?? '';
    i += name.length;
    if (name === 'frac' || name === 'tfrac' || name === 'dfrac') return `${group(argument())}/${group(argument())}`;
    if (name === 'sqrt') return `√${group(argument())}`;
    if (KEEP_ARGUMENT.has(name)) return argument();
    if (name === 'left' || name === 'right' || name === 'big' || name === 'Big') return '';
    return SYMBOLS[name] ?? name; // \max, \exp, \cos … read as their names
  };
  /** @param {string} until */
  const sequence = (until) => {
    let out = '';
    while (i < src.length && src[i] !== until) {
      const c = src[i];
      if (c === '^' || c === '_') {
        i++;
        const arg = argument();
        const sup = [...arg].map((d) => SUPERSCRIPT[d]);
        out += c === '^' && sup.every(Boolean) ? sup.join('') : `${c}${group(arg)}`;
      } else out += atom();
    }
    i++;
    return out;
  };
  return sequence('').replace(/\s+/g, ' ').trim();
}

/**
 * Fills `el` with `source`: text nodes, and a data-tex span for each formula (typeset it with typesetFormulas).
 * @param {HTMLElement} el
 * @param {string} source
 */
export function setInlineTex(el, source) {
  el.replaceChildren(
    ...parseInlineTex(source).map((p) => {
      if ('text' in p) return document.createTextNode(p.text);
      const span = document.createElement('span');
      span.dataset.tex = p.tex;
      span.textContent = p.plain;
      return span;
    }),
  );
}
