// The way on at the end of a chapter page: links to the chapters before and after it in the talk's order
// (CHAPTERS), written into the page's HTML when it is built (vite.config.js), so they work without script.
import { CHAPTERS } from './chapters.js';

/** A chapter's title as the landing page and the header number it. */
const numbered = (i) => `${i + 1}. ${CHAPTERS[i].title}`;

/**
 * The previous and next chapter of the page `file` (e.g. 'fresnel.html'), or null when it is no chapter's page.
 * @param {string} file
 * @returns {{ prev: { href: string, title: string } | null, next: { href: string, title: string } | null } | null}
 */
export function chapterNeighbours(file) {
  const at = CHAPTERS.findIndex((ch) => ch.page === file);
  if (at < 0) return null;
  const link = (i) => (CHAPTERS[i]?.page ? { href: CHAPTERS[i].page, title: numbered(i) } : null);
  return { prev: link(at - 1), next: link(at + 1) };
}

/**
 * The pager's HTML for the page `file`: '' when it is no chapter's page.
 * @param {string} file
 */
export function chapterPagerHtml(file) {
  const around = chapterNeighbours(file);
  if (!around) return '';
  const { prev, next } = around;
  const a = (to, rel, dir) =>
    `<a class="pager-${rel}" rel="${rel}" href="${to.href}"><span class="pager-dir">${dir}</span> ` +
    `<span class="pager-title">${to.title}</span></a>`;
  return (
    '<nav class="chapter-pager" aria-label="Previous and next chapter">' +
    (prev ? a(prev, 'prev', '← Previous chapter') : '<a class="pager-prev" href="./">← All chapters</a>') +
    (next ? a(next, 'next', 'Next chapter →') : '<a class="pager-next" href="./">All chapters →</a>') +
    '</nav>'
  );
}
