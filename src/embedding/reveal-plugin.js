// A reveal.js plugin over <shading-lab-widget> (README, "Embedding"):
//   <section data-shading-lab="fresnel-zones?mode=zones-lh"> … a widget on this slide, in this state
//   <span class="fragment" data-shading-lab-set="mode=zones-lh-weighted"> … applied when the fragment is
//     shown, taken back when it is hidden (the slide's state is its own plus its visible fragments', in order)
// Only the current slide and its neighbours hold a live widget, so a long deck stays under the browser's cap
// on WebGL contexts. In reveal's print view (?print-pdf) each widget becomes a still image in the state of
// its printed page. The widget sits in the slide's [data-shading-lab-slot] element (whose height is the page's),
// or in one added at its end, which takes the widget's height (its `resize`) up to the room left on the slide.
// `presenter: true` in the config (or data-shading-lab-presenter on a slide) shows the views only, filling the slot.
//
//   import ShadingLab from 'https://lab.example.org/shading-lab-reveal.js';
//   Reveal.initialize({ shadingLab: { src: 'https://lab.example.org/embed.html' }, plugins: [ShadingLab] });

// The element is loaded from beside this file at run time, not bundled in: both stay single files in dist/.
// (A file beside this one, named without new URL(…, import.meta.url), which the build would take as an asset.)
const beside = (file) => import.meta.url.replace(/[^/?#]*([?#].*)?$/, file);
const LIVE_DISTANCE = 1; // slides on each side of the current one that keep their widget
const SLOT_HEIGHT = '480px'; // of a slot the plugin adds, until its widget tells its height (a slide: 960 × 700)
const ADDED = 'added'; // the data-shading-lab-slot value of a slot the plugin added

/** "fresnel-zones?mode=zones-lh" → { name, query }. */
export function parseWidgetSpec(spec) {
  const [name, query = ''] = String(spec ?? '')
    .trim()
    .split(/\?(.*)/s);
  return { name, query };
}

/** The fragments' state changes visible in `section`, in reveal's fragment order, merged into one object. */
export function visibleSets(section) {
  const sets = [...section.querySelectorAll('.fragment.visible[data-shading-lab-set]')]
    .map((el, i) => ({ at: Number(el.dataset.fragmentIndex ?? Infinity), i, query: el.dataset.shadingLabSet }))
    .sort((a, b) => a.at - b.at || a.i - b.i);
  return Object.assign({}, ...sets.map((s) => Object.fromEntries(new URLSearchParams(s.query))));
}

function slotOf(section) {
  let slot = section.querySelector('[data-shading-lab-slot]');
  if (!slot) {
    slot = document.createElement('div');
    slot.dataset.shadingLabSlot = ADDED;
    slot.style.height = SLOT_HEIGHT;
    section.append(slot);
  }
  return slot;
}

/** Whether `section` shows the presenter view: its data-shading-lab-presenter, else the deck's `presenter`. */
export function isPresenter(section, deckDefault = false) {
  const own = section.dataset.shadingLabPresenter;
  return own === undefined ? Boolean(deckDefault) : own !== 'false';
}

/**
 * A slot the plugin added takes its widget's height, up to the room left below the slot on a slide `slideHeight`
 * tall; an author's slot keeps the height the author gave it.
 */
function followHeight(slot, el, slideHeight, relayout) {
  if (slot.dataset.shadingLabSlot !== ADDED) return;
  el.addEventListener('resize', (e) => {
    const room = slideHeight - slot.offsetTop;
    slot.style.height = `${Math.max(0, Math.min(e.detail.height, room))}px`;
    relayout();
  });
}

/** A widget element for `section` (its slide's own state; the fragments' are applied once it is ready). */
function widgetFor(section, { src, presenter }) {
  const { name, query } = parseWidgetSpec(section.dataset.shadingLab);
  const el = document.createElement('shading-lab-widget');
  el.setAttribute('name', name);
  el.setAttribute('state', query);
  el.setAttribute('src', src);
  if (isPresenter(section, presenter)) el.setAttribute('presenter', '');
  el.style.height = '100%'; // the slot's: the element does not resize itself, the plugin resizes an added slot
  return el;
}

function createPlugin() {
  const base = new WeakMap(); // element → its whole state when ready, before any fragment
  let deck = null;
  let options = { src: '', presenter: false };

  /** The slide's state: its own, with its visible fragments' sets over it. */
  const apply = (section) => {
    const el = section.querySelector('shading-lab-widget');
    if (el && base.has(el)) el.set({ ...base.get(el), ...visibleSets(section) });
  };

  const mount = (section) => {
    const el = widgetFor(section, options);
    el.addEventListener('ready', () => (base.set(el, el.state), apply(section)), { once: true });
    const slot = slotOf(section);
    followHeight(slot, el, deck.getConfig().height, () => deck.layout());
    slot.replaceChildren(el);
  };

  /** Live widgets on the current slide and its neighbours; none elsewhere. */
  const refresh = () => {
    const slides = deck.getSlides();
    const current = slides.indexOf(deck.getCurrentSlide());
    slides.forEach((section, i) => {
      if (!section.hasAttribute('data-shading-lab')) return;
      const live = section.querySelector('shading-lab-widget');
      if (Math.abs(i - current) > LIVE_DISTANCE) live?.remove();
      else if (!live) mount(section);
      else apply(section);
    });
  };

  const onFragment = (e) => {
    const section = e.fragment?.closest('section[data-shading-lab]');
    if (section) apply(section);
  };

  return {
    id: 'shading-lab',
    printed: null, // in the print view: a promise, settled when every widget is a still image
    async init(reveal) {
      await import(/* @vite-ignore */ beside('shading-lab-widget.js'));
      deck = reveal;
      const config = deck.getConfig().shadingLab ?? {};
      options = { src: config.src ?? beside('embed.html'), presenter: Boolean(config.presenter) };
      // every slot before reveal lays the slides out (the print view centres each by its height once)
      deck.getRevealElement().querySelectorAll('section[data-shading-lab]').forEach(slotOf);
      if (deck.isPrintView()) {
        this.printed = new Promise((done) => deck.on('pdf-ready', () => printStills(options).then(done)));
        return;
      }
      deck.on('ready', refresh);
      deck.on('slidechanged', refresh);
      deck.on('fragmentshown', onFragment);
      deck.on('fragmenthidden', onFragment);
    },
  };
}

/**
 * The print view: every printed page's widget, one at a time (one WebGL context at a time), is mounted in
 * the page's state, pictured and replaced by the picture. Marks the deck data-shading-lab-printed when done.
 */
async function printStills(options) {
  for (const section of document.querySelectorAll('.pdf-page section[data-shading-lab]')) {
    section.closest('.pdf-page')?.scrollIntoView(); // a 3-D view takes a WebGL context only near sight
    const el = widgetFor(section, options);
    const ready = new Promise((ok) => el.addEventListener('ready', ok, { once: true }));
    slotOf(section).replaceChildren(el);
    await ready;
    await el.set(visibleSets(section));
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const image = (await el.snapshot()) ?? '';
    const alt = `${el.getAttribute('name')}: ${el.query}`;
    const img = Object.assign(document.createElement('img'), { src: image, alt });
    img.style.cssText = 'display: block; width: 100%; height: 100%; object-fit: contain';
    el.replaceWith(img);
  }
  document.querySelector('.reveal')?.setAttribute('data-shading-lab-printed', '');
}

/** reveal.js calls a plugin function to get the plugin: one per deck. */
export default createPlugin;
