// Typeset formulas: every element with data-tex="…" (TeX, in the talk's notation) is replaced by MathML made by
// KaTeX, which the browser draws and screen readers read; its text content is the plain fallback shown until then
// (and to a browser without MathML). KaTeX is loaded only on a page that has a formula. No CSS or fonts needed.

// MathML Core (Chromium) draws no mathvariant but "normal": the talk's bold vectors become the Unicode
// mathematical bold letters (U+1D400 A…Z, U+1D41A a…z), which every MathML renderer shows bold.
const BOLD = { A: 0x1d400, a: 0x1d41a };
function boldLetters(math) {
  for (const mi of math.querySelectorAll('mi[mathvariant="bold"]')) {
    const c = mi.textContent;
    if (!/^[A-Za-z]$/.test(c)) continue;
    const base = c >= 'a' ? BOLD.a + c.charCodeAt(0) - 97 : BOLD.A + c.charCodeAt(0) - 65;
    mi.textContent = String.fromCodePoint(base);
    mi.removeAttribute('mathvariant');
  }
}

/** Typesets the formulas under `root`; a formula KaTeX cannot parse keeps its fallback text (and says why). */
export async function typesetFormulas(root = document) {
  const elements = [...root.querySelectorAll('[data-tex]')];
  if (!elements.length) return 0;
  const { default: katex } = await import('katex');
  for (const el of elements) {
    try {
      const fallback = el.textContent.trim();
      katex.render(el.dataset.tex, el, { output: 'mathml', displayMode: el.tagName !== 'SPAN', throwOnError: true });
      boldLetters(el);
      el.title = fallback; // the plain form, on hover
    } catch (e) {
      el.title = `Formula not typeset: ${e.message}`;
    }
  }
  return elements.length;
}
