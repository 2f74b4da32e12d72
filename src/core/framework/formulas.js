// @ts-check
// Typeset formulas: every element with data-tex="…" (TeX, in the talk's notation) is replaced by MathML made by
// KaTeX, which the browser draws and screen readers read; its text content is the plain fallback shown until then
// (and to a browser without MathML). KaTeX is loaded only on a page that has a formula. No CSS or fonts needed.

import { TALK_MACROS } from './formula-registry.js';
import { whileLoading } from './debug-hooks.js';

/** @typedef {typeof import('katex').default} Katex */

// MathML Core (Chromium) draws no mathvariant but "normal": the talk's bold vectors become the Unicode
// mathematical bold letters (U+1D400 A…Z, U+1D41A a…z), which every MathML renderer shows bold.
const BOLD = { A: 0x1d400, a: 0x1d41a };
/** @param {Element} math */
function boldLetters(math) {
  for (const mi of math.querySelectorAll('mi[mathvariant="bold"]')) {
    const c = mi.textContent ?? '';
    if (!/^[A-Za-z]$/.test(c)) continue;
    const base = c >= 'a' ? BOLD.a + c.charCodeAt(0) - 97 : BOLD.A + c.charCodeAt(0) - 65;
    mi.textContent = String.fromCodePoint(base);
    mi.removeAttribute('mathvariant');
  }
}

/** KaTeX, loaded once, when the first formula is typeset. */
export const loadKatex = async () => /** @type {Katex} */ ((await whileLoading(import('katex'))).default);

/**
 * Replaces the content of `el` by the MathML of `tex` (throws on TeX that KaTeX cannot parse).
 * @param {Katex} katex
 * @param {HTMLElement} el
 * @param {string} tex
 * @param {import('katex').KatexOptions} [options]
 */
export function typeset(katex, el, tex, options = {}) {
  const macros = { ...TALK_MACROS, ...options.macros };
  katex.render(tex, el, {
    output: 'mathml',
    displayMode: el.tagName !== 'SPAN',
    throwOnError: true,
    ...options,
    macros,
  });
  boldLetters(el);
}

/**
 * Typesets the formulas under `root` (each once); a formula KaTeX cannot parse keeps its fallback text (and
 * says why).
 * @param {ParentNode} [root]
 */
export async function typesetFormulas(root = document) {
  const elements = /** @type {HTMLElement[]} */ ([...root.querySelectorAll('[data-tex]:not([data-typeset])')]);
  if (!elements.length) return 0;
  const katex = await loadKatex();
  for (const el of elements) {
    if (el.dataset.typeset) continue; // a second call while KaTeX loaded
    el.dataset.typeset = '1';
    try {
      const fallback = el.textContent?.trim() ?? '';
      typeset(katex, el, el.dataset.tex ?? '');
      el.title = fallback; // the plain form, on hover
    } catch (e) {
      el.title = `Formula not typeset: ${e instanceof Error ? e.message : e}`;
    }
  }
  return elements.length;
}
