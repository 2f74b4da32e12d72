// <shading-lab-widget name="fresnel-zones" state="mode=zones-lh" src="https://lab.example.org/embed.html">:
// one widget of the app in any page, over the postMessage protocol of embed.html (README, "Embedding").
// It makes the iframe (allowing this page's origin to message it), keeps the widget's state, and offers
//   el.state          the widget's whole state (null until ready); assigning it is el.set(value)
//   el.query          the same as URL parameters, only what differs from the defaults
//   el.set(partial)   an object or a query string; → Promise<{ state, query, errors }>
//   el.snapshot()     → Promise<PNG data URL> of what the widget shows
//   events            'ready' and 'change' (the user moved the widget), detail { state, query }; 'resize', detail
//                     { height }: the widget's content height, which the element takes unless its height is fixed
// Its height follows the widget's (no scroll bar inside) unless the page fixed it in the element's style
// attribute (style="height: 480px", or el.style.height): then the widget scrolls inside that height. The
// `presenter` attribute shows the views only, filling the element (4 : 3 unless its height is fixed).
// Built alone into dist/shading-lab-widget.js: it imports nothing, so the page embedding it loads no three.js.

// The protocol's message prefix (src/core/framework/embed-protocol.js MESSAGE_PREFIX; a unit test holds them equal).
export const PREFIX = 'shading-lab:';
const HELLO_MS = 250; // how often to ask a widget that has not said `ready` (a browser that hides the parent's origin)
const HELLO_TRIES = 120;

const toPartial = (value) =>
  typeof value === 'string' ? Object.fromEntries(new URLSearchParams(value)) : { ...(value ?? {}) };

/** The iframe's URL: `src` with the widget's name, its state and this page's origin (allowed to message it). */
export function frameUrl(src, name, state, pageOrigin, base, presenter = false) {
  const url = new URL(src, base);
  url.searchParams.set('w', name);
  if (presenter) url.searchParams.set('presenter', '1');
  for (const [k, v] of new URLSearchParams(state ?? '')) url.searchParams.set(k, v);
  if (pageOrigin !== url.origin && pageOrigin !== 'null') url.searchParams.set('origins', pageOrigin);
  return url;
}

// In Node (unit tests) there is no HTMLElement: the class is still defined, the element is not registered.
export class ShadingLabWidget extends (globalThis.HTMLElement ?? class {}) {
  static observedAttributes = ['name', 'src', 'state', 'presenter'];

  #frame = null;
  #origin = '';
  #state = null;
  #query = '';
  #queue = []; // messages waiting for `ready`
  #pending = new Map(); // id → { resolve, reject, errors }
  #nextId = 1;
  #hello = 0;
  #height = ''; // the style height this element gave itself from the widget's `resize` ('' for none yet)
  #onMessage = (e) => this.#receive(e);

  get state() {
    return this.#state && structuredClone(this.#state);
  }

  set state(value) {
    this.set(value);
  }

  get query() {
    return this.#query;
  }

  get ready() {
    return this.#state !== null;
  }

  /** Changes some fields (validated by the widget: clamped, bad values kept, unknown keys reported). */
  set(partial) {
    return this.#request({ type: `${PREFIX}set`, state: toPartial(partial) });
  }

  /** What the widget shows now, as a PNG data URL. */
  snapshot() {
    return this.#request({ type: `${PREFIX}snapshot` }).then((r) => r.image);
  }

  connectedCallback() {
    this.#mount();
  }

  disconnectedCallback() {
    this.#unmount();
  }

  attributeChangedCallback(attr, before, after) {
    if (!this.isConnected || before === after) return;
    if (attr === 'state' && this.ready) this.set(after ?? '');
    else this.#mount(); // a new widget or host, or a state given before the frame was ready: a new frame
  }

  #mount() {
    this.#unmount();
    const name = this.getAttribute('name');
    const src = this.getAttribute('src');
    if (!name || !src) return;
    const presenter = this.hasAttribute('presenter');
    const url = frameUrl(src, name, this.getAttribute('state'), location.origin, document.baseURI, presenter);
    this.#origin = url.origin;
    const frame = document.createElement('iframe');
    frame.src = url.href;
    frame.title = this.getAttribute('title') || `Shading Lab: ${name}`;
    frame.style.cssText = 'display: block; width: 100%; height: 100%; border: 0';
    frame.addEventListener('load', () => this.#sayHello());
    this.#frame = frame;
    if (!this.style.display) this.style.display = 'block';
    if (presenter && !this.#fixed() && !this.style.aspectRatio) this.style.aspectRatio = '4 / 3';
    window.addEventListener('message', this.#onMessage);
    this.replaceChildren(frame);
  }

  #unmount() {
    clearInterval(this.#hello);
    window.removeEventListener('message', this.#onMessage);
    for (const p of this.#pending.values()) p.reject(new Error('shading-lab-widget: the widget was removed'));
    this.#pending.clear();
    this.#queue = [];
    this.#state = null;
    this.#frame?.remove();
    this.#frame = null;
  }

  /** True when the page, not the widget, sets the height: a style height this element did not give itself. */
  #fixed() {
    return this.style.height !== '' && this.style.height !== this.#height;
  }

  #resize(height) {
    if (!(height > 0) || height > 1e5) return; // not a height (a frame tall enough for anything is a bug)
    if (!this.#fixed()) this.style.height = this.#height = `${Math.ceil(height)}px`;
    this.dispatchEvent(new CustomEvent('resize', { detail: { height } }));
  }

  // A browser that reveals neither ancestorOrigins nor the referrer lets the widget talk only once asked.
  #sayHello() {
    let tries = 0;
    clearInterval(this.#hello);
    this.#hello = setInterval(() => {
      if (this.ready || ++tries > HELLO_TRIES) clearInterval(this.#hello);
      else this.#frame?.contentWindow?.postMessage({ type: `${PREFIX}get` }, this.#origin);
    }, HELLO_MS);
  }

  #request(message) {
    const id = `el-${this.#nextId++}`;
    return new Promise((resolve, reject) => {
      this.#pending.set(id, { resolve, reject, errors: [] });
      this.#post({ ...message, id });
    });
  }

  #post(message) {
    if (this.ready) this.#frame.contentWindow.postMessage(message, this.#origin);
    else this.#queue.push(message);
  }

  #receive(e) {
    if (!this.#frame || e.source !== this.#frame.contentWindow || e.origin !== this.#origin) return;
    const m = e.data;
    if (typeof m?.type !== 'string' || !m.type.startsWith(PREFIX)) return;
    const kind = m.type.slice(PREFIX.length);
    const wasReady = this.ready;
    if (m.state) [this.#state, this.#query] = [m.state, m.query];
    if (!wasReady && this.ready) this.#becomeReady();
    const pending = this.#pending.get(m.id);
    if (kind === 'resize') this.#resize(m.height);
    else if (kind === 'changed') this.#emit('change');
    else if (kind === 'error' && pending) pending.errors.push(...m.errors);
    else if ((kind === 'state' || kind === 'snapshot') && pending) {
      this.#pending.delete(m.id);
      pending.resolve({ state: this.state, query: this.#query, errors: pending.errors, image: m.image });
    }
  }

  #becomeReady() {
    clearInterval(this.#hello);
    this.#emit('ready');
    const queued = this.#queue;
    this.#queue = [];
    queued.forEach((m) => this.#post(m));
  }

  #emit(type) {
    this.dispatchEvent(new CustomEvent(type, { detail: { state: this.state, query: this.#query } }));
  }
}

if (globalThis.customElements && !customElements.get('shading-lab-widget')) {
  customElements.define('shading-lab-widget', ShadingLabWidget);
}
