// @ts-check
// A widget's live formula: the formula it evaluates (declared in its words.js, formula-registry.js), with the
// current values substituted, typeset as MathML under the widget's view. Re-typeset at most once a frame and
// only when the TeX changes, so a drag costs one string per step. Each \sym{key}{…} symbol is tied to the
// control of state key `key`: hovering or focusing either lights both up; Enter on a symbol focuses its control.
import { FORMULA_MACROS } from './formula-registry.js';
import { loadKatex, typeset } from './formulas.js';

const LIT = 'is-lit';
const SYMBOL_URL = '#sym:';

/** @type {import('katex').KatexOptions['trust']} the symbols' \href only */
const trust = (context) => context.command === '\\href' && context.url.startsWith(SYMBOL_URL);

/**
 * The element of each state key's control in a lil-gui panel made by gui.js: a field's controller, or the
 * folder of a set field's checkboxes.
 * @param {import('lil-gui').GUI} gui
 * @param {import('./types.js').Schema} schema
 * @returns {Map<string, HTMLElement>}
 */
export function controlElements(gui, schema) {
  /** @type {Map<string, HTMLElement>} */
  const out = new Map();
  for (const c of gui.controllersRecursive()) {
    const field = schema[c.property]; // a set's checkboxes are named by option, not key: they come below
    if (field && field.type !== 'set') out.set(c.property, c.domElement);
  }
  for (const folder of gui.foldersRecursive()) {
    const isSetOf = (/** @type {string} */ k) =>
      schema[k].type === 'set' && folder._title.startsWith(schema[k].label ?? k);
    const key = Object.keys(schema).find(isSetOf);
    if (key) out.set(key, folder.domElement);
  }
  return out;
}

/**
 * Shows `texOf(state)` in a new element placed after `anchor`.
 * @param {HTMLElement} anchor
 * @param {import('./formula-registry.js').FormulaOf} texOf
 */
export function createLiveFormula(anchor, texOf) {
  const el = document.createElement('div');
  el.className = 'formula widget-formula';
  el.hidden = true; // until KaTeX has loaded and typeset it
  anchor.after(el);
  /** @type {Map<string, HTMLElement>} */
  let controls = new Map();
  /** @type {Set<string>} */
  const lit = new Set();
  let shown = '';
  /** @type {import('./types.js').State | null} */
  let latest = null;
  let frame = 0;
  /** @type {import('./formulas.js').Katex | null} */
  let katex = null;
  let disposed = false;

  const symbols = (/** @type {string} */ key) => el.querySelectorAll(`[data-symbol="${CSS.escape(key)}"]`);
  const light = (/** @type {string} */ key, /** @type {boolean} */ on) => {
    if (on) lit.add(key);
    else lit.delete(key);
    controls.get(key)?.classList.toggle(LIT, on);
    for (const s of symbols(key)) s.classList.toggle(LIT, on);
  };

  const render = () => {
    frame = 0;
    if (!katex || disposed || !latest) return;
    const wanted = texOf(latest); // once a frame at most, however often the state changed
    if (wanted === shown) return;
    try {
      typeset(katex, el, wanted, { macros: { ...FORMULA_MACROS }, trust });
    } catch (e) {
      console.warn(`live formula not typeset: ${e instanceof Error ? e.message : e}`);
      return; // keeps the last good formula
    }
    shown = wanted;
    el.hidden = false;
    for (const s of el.querySelectorAll(`[href^="${SYMBOL_URL}"]`)) tagSymbol(s, controls, lit);
  };
  const schedule = () => {
    if (!frame) frame = requestAnimationFrame(render);
  };
  loadKatex().then((k) => {
    katex = k;
    schedule();
  });

  listenToSymbols(el, light, (key) =>
    controls
      .get(key)
      ?.querySelector(/** @type {'input'} */ ('input, select, button'))
      ?.focus(),
  );
  const unlink = new AbortController();

  return {
    element: el,
    /** @param {import('./types.js').State} state */
    show(state) {
      latest = state;
      schedule();
    },
    /**
     * Ties the symbols to these controls (state key → control element).
     * @param {Map<string, HTMLElement>} byKey
     */
    link(byKey) {
      controls = byKey;
      for (const [key, control] of byKey) {
        for (const [type, on] of /** @type {const} */ ([
          ['pointerenter', true],
          ['pointerleave', false],
          ['focusin', true],
          ['focusout', false],
        ])) {
          control.addEventListener(type, () => light(key, on), { signal: unlink.signal });
        }
      }
      shown = ''; // re-tag the symbols against these controls
      schedule();
    },
    dispose() {
      disposed = true;
      cancelAnimationFrame(frame);
      unlink.abort();
      el.remove();
    },
  };
}

/**
 * Hovering or focusing a symbol of `el` lights it (and its control) up; Enter on it goes to its control.
 * @param {HTMLElement} el
 * @param {(key: string, on: boolean) => void} light
 * @param {(key: string) => void} goTo
 */
function listenToSymbols(el, light, goTo) {
  const keyOf = (/** @type {Event} */ e) =>
    /** @type {Element} */ (e.target).closest?.('[data-symbol]')?.getAttribute('data-symbol');
  const on = (/** @type {boolean} */ lit) => (/** @type {Event} */ e) => {
    const key = keyOf(e);
    if (key) light(key, lit);
  };
  el.addEventListener('pointerover', on(true));
  el.addEventListener('pointerout', on(false));
  el.addEventListener('focusin', on(true));
  el.addEventListener('focusout', on(false));
  el.addEventListener('keydown', (e) => {
    const key = keyOf(e);
    if (e.key === 'Enter' && key) goTo(key);
  });
}

/**
 * Turns KaTeX's \href{#sym:key} into a symbol: data-symbol="key", focusable when its control exists.
 * @param {Element} s
 * @param {Map<string, HTMLElement>} controls
 * @param {Set<string>} lit
 */
function tagSymbol(s, controls, lit) {
  const key = (s.getAttribute('href') ?? '').slice(SYMBOL_URL.length);
  s.removeAttribute('href');
  s.setAttribute('data-symbol', key);
  s.classList.add('formula-symbol');
  if (lit.has(key)) s.classList.add(LIT);
  const control = controls.get(key);
  if (!control) return;
  s.setAttribute('tabindex', '0');
  const name = control.querySelector('.lil-name, .title')?.textContent;
  if (name) s.setAttribute('title', `Set by “${name}” (Enter goes to it)`);
}
