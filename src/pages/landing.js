// The landing page: every chapter in the talk's order, live ones linked with their widgets.
import '../styles.css';
import { CHAPTERS } from './chapters.js';
import { WIDGETS } from '../widgets/registry.js';
import { CHAPTER_PICTURES, CHAPTER_PICTURE_SIZE, chapterPictureUrl } from './chapter-pictures.js';

/** The chapter's picture, linked to its page when it has one. */
function picture(ch) {
  const img = Object.assign(document.createElement('img'), {
    src: chapterPictureUrl(ch.key),
    alt: CHAPTER_PICTURES[ch.key],
    className: 'chapter-picture',
    loading: 'lazy',
    decoding: 'async',
    ...CHAPTER_PICTURE_SIZE,
  });
  if (!ch.page) return img;
  // the title is the link for keyboards: the picture's link is for the pointer only
  const a = Object.assign(document.createElement('a'), { href: ch.page, tabIndex: -1 });
  a.append(img);
  return a;
}

const list = document.getElementById('chapters');
CHAPTERS.forEach((ch, i) => {
  const li = document.createElement('li');
  li.className = ch.page ? 'chapter live' : 'chapter coming';
  const title = ch.page
    ? Object.assign(document.createElement('a'), { href: ch.page })
    : document.createElement('span');
  title.className = 'chapter-title';
  title.textContent = `${i + 1}. ${ch.title}`;
  const blurb = document.createElement('p');
  blurb.textContent = ch.blurb;
  if (CHAPTER_PICTURES[ch.key]) li.append(picture(ch));
  li.append(title, blurb);
  if (!ch.page) {
    const tag = document.createElement('span');
    tag.className = 'tag';
    tag.textContent = 'coming';
    title.append(' ', tag);
  }
  if (ch.widgets) {
    const ul = document.createElement('ul');
    ul.className = 'widget-links';
    for (const name of ch.widgets) {
      const w = document.createElement('li');
      const a = Object.assign(document.createElement('a'), {
        href: `embed.html?w=${name}`,
        textContent: WIDGETS[name].title,
      });
      w.append(a, ` — ${WIDGETS[name].summary}`);
      ul.append(w);
    }
    li.append(ul);
  }
  list.append(li);
});
