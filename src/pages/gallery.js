// gallery.html: every registered widget with a live preview (loaded when scrolled to) and the iframe snippet
// that embeds it in the state the preview shows, as tall as the preview has been. The previews report their state
// and height through the embed protocol (src/core/framework/embed-protocol.js); the gallery is on their origin,
// so they talk to it by default.
import '../styles.css';
import { MESSAGE_PREFIX } from '../core/framework/embed-protocol.js';
import { WIDGETS } from '../widgets/registry.js';

const PREVIEW_HEIGHT = 600; // px: the placeholder's, until the preview tells its height
const NEAR_VIEW = '300px 0px'; // start loading a preview a little before it scrolls in

const escapeAttr = (s) => s.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');

/** The embed URL of a widget in a state given as URL parameters, absolute, from this page's location. */
const embedUrl = (name, query) =>
  new URL(`embed.html?w=${encodeURIComponent(name)}${query ? `&${query}` : ''}`, location.href).href;

const snippetFor = (name, query, height) =>
  `<iframe src="${escapeAttr(embedUrl(name, query))}" title="${escapeAttr(`${WIDGETS[name].title} — Shading Lab`)}" ` +
  `width="100%" height="${height}" style="border: 0" loading="lazy"></iframe>`;

async function copy(textarea, status) {
  try {
    await navigator.clipboard.writeText(textarea.value);
    status.textContent = 'Copied.';
  } catch {
    // no clipboard access (an insecure origin, or permission refused): leave the text selected for Ctrl+C
    textarea.focus();
    textarea.select();
    status.textContent = 'Selected: press Ctrl+C (⌘C) to copy.';
  }
}

function card(name) {
  const { title, summary } = WIDGETS[name];
  const article = document.createElement('article');
  article.className = 'gallery-card';
  article.id = name; // the index's link target: gallery.html#fresnel-zones
  article.dataset.widget = name;
  const h2 = Object.assign(document.createElement('h2'), { id: `${name}-h`, textContent: title });
  const p = Object.assign(document.createElement('p'), { textContent: summary });
  const preview = document.createElement('div');
  preview.className = 'gallery-preview';
  preview.style.height = `${PREVIEW_HEIGHT}px`;
  preview.textContent = 'The live preview loads when you scroll to it.';

  const label = Object.assign(document.createElement('label'), {
    htmlFor: `${name}-snippet`,
    textContent: 'Embed code',
  });
  const snippet = Object.assign(document.createElement('textarea'), {
    id: `${name}-snippet`,
    readOnly: true,
    rows: 3,
    value: snippetFor(name, '', PREVIEW_HEIGHT),
  });
  snippet.className = 'gallery-snippet';
  snippet.spellcheck = false;
  snippet.addEventListener('focus', () => snippet.select());
  const button = Object.assign(document.createElement('button'), { type: 'button', textContent: 'Copy' });
  button.setAttribute('aria-describedby', `${name}-h`);
  const status = Object.assign(document.createElement('span'), { className: 'gallery-status' });
  status.setAttribute('role', 'status');
  button.addEventListener('click', () => copy(snippet, status));
  const row = document.createElement('div');
  row.className = 'gallery-copy';
  row.append(button, status);

  article.append(h2, p, preview, label, snippet, row);
  let frame = null;
  let query = '';
  // the tallest the widget has been (a probe table that appeared once keeps its room): a frame that tall never
  // cuts the widget off at the width it was measured at
  let height = 0;
  const write = () => (snippet.value = snippetFor(name, query, height || PREVIEW_HEIGHT));
  return {
    article,
    preview,
    load() {
      frame = Object.assign(document.createElement('iframe'), {
        title: `${title} (live preview)`,
        src: embedUrl(name, ''),
      });
      preview.replaceChildren(frame);
    },
    /** A message from this card's preview: `ready`, `changed` or `state` carry the state as URL parameters. */
    owns: (source) => frame?.contentWindow === source,
    setQuery(q) {
      query = q;
      write();
      status.textContent = '';
    },
    /** The preview's content height (its `resize`): the preview takes it, the snippet the tallest so far. */
    setHeight(h) {
      preview.style.height = ''; // the preview wraps its frame (and its border)
      frame.style.height = `${h}px`;
      height = Math.max(height, h);
      write();
    },
  };
}

/** The page's index: a link to every widget's card, in the gallery's order. */
function index(names) {
  const nav = document.createElement('nav');
  nav.className = 'gallery-index';
  nav.setAttribute('aria-labelledby', 'gallery-index-h');
  const h = Object.assign(document.createElement('h2'), { id: 'gallery-index-h', textContent: 'The widgets' });
  const ol = document.createElement('ol');
  for (const name of names) {
    const li = document.createElement('li');
    li.append(Object.assign(document.createElement('a'), { href: `#${name}`, textContent: WIDGETS[name].title }));
    ol.append(li);
  }
  nav.append(h, ol);
  return nav;
}

const cards = Object.keys(WIDGETS).map(card);
const gallery = document.getElementById('gallery');
gallery.before(index(Object.keys(WIDGETS)));
gallery.append(...cards.map((c) => c.article));

const lazy = new IntersectionObserver(
  (entries) => {
    for (const e of entries.filter((x) => x.isIntersecting)) {
      lazy.unobserve(e.target);
      cards.find((c) => c.preview === e.target).load();
    }
  },
  { rootMargin: NEAR_VIEW },
);
cards.forEach((c) => lazy.observe(c.preview));

const STATE_MESSAGES = new Set(['ready', 'changed', 'state'].map((t) => `${MESSAGE_PREFIX}${t}`));
window.addEventListener('message', (e) => {
  if (e.origin !== location.origin) return;
  const card = cards.find((c) => c.owns(e.source));
  const { type, query, height } = e.data ?? {};
  if (STATE_MESSAGES.has(type) && typeof query === 'string') card?.setQuery(query);
  else if (type === `${MESSAGE_PREFIX}resize` && Number.isFinite(height) && height > 0) card?.setHeight(height);
});
