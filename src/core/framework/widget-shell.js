// @ts-check
// The common frame of every widget: its root element, notice area, a view and a control column, and the
// one state object, validated on every way in (initial state, update(), GUI).
import { coerceState, currentNames, defaultState, fieldOf } from './state.js';
import { STATE_NOTICES, createNoticeArea } from './notice.js';
import { createStateGui } from './gui.js';
import { createLiveRegion, describeCanvas } from './describe.js';
import { createShareBar, linkChoices, shareLink } from './share.js';
import { registerPrintable } from './print.js';
import { declaredFormula } from './formula-registry.js';
import { controlElements, createLiveFormula } from './live-formula.js';

/**
 * @typedef {object} ShellSpec
 * @property {string} name  the widget's name (its class, data-widget and share links)
 * @property {import('./types.js').Schema} schema
 * @property {Partial<Record<string, unknown>>} [initialState]  create's second argument, as given
 * @property {string[]} [locked]  create's `options.locked`: their controls are disabled and later updates leave
 *   them alone
 * @property {string} [about]  HTML of the paragraph under the widget
 * @property {string[]} [terms]  math functions it uses, linked to the parity page
 */

/**
 * The frame of a widget (the contract it fulfils: src/core/framework/types.js).
 * @param {HTMLElement} container
 * @param {ShellSpec} spec
 */
export function createWidgetShell(
  container,
  { name, schema, initialState, locked: lockedKeys = [], about, terms = [] },
) {
  // a locked old name goes where its value in the initial state went (the lab's old `diffuse`, a colour: cdiff)
  const locked = lockedKeys.map((k) => fieldOf(schema, k, initialState?.[k])).filter((k) => Object.hasOwn(schema, k));
  const root = document.createElement('section');
  root.className = `widget widget-${name}`;
  root.dataset.widget = name;
  const notices = createNoticeArea(root);
  const body = document.createElement('div');
  body.className = 'widget-body';
  const view = document.createElement('div');
  view.className = 'widget-view';
  const controls = document.createElement('div');
  controls.className = 'widget-controls';
  body.append(view, controls);
  root.append(body);
  if (about) {
    const p = document.createElement('p');
    p.className = 'widget-about';
    p.innerHTML = about;
    root.append(p);
  }
  if (terms.length) root.append(termLinks(terms));
  container.append(root);
  const live = createLiveRegion(root);

  const first = coerceState(schema, initialState, defaultState(schema));
  if (first.notices.length) notices.show(first.notices);
  let state = first.state;
  const texOf = declaredFormula(name); // the widget's live formula, declared in its words.js
  const formula = texOf ? createLiveFormula(body, texOf) : null;
  formula?.show(state);
  /** @type {ReturnType<typeof createStateGui> | null} */
  let gui = null;
  /** @type {(() => void) | null} */
  let unprint = null;

  /**
   * Validates `partial` against the current state; returns the keys whose value changed.
   * @param {Partial<Record<string, unknown>> | undefined} partial
   */
  const apply = (partial) => {
    const free = Object.fromEntries(Object.entries(currentNames(schema, partial)).filter(([k]) => !locked.includes(k)));
    const next = coerceState(schema, free, state);
    if (next.notices.length) reportNotices(root, notices, next.notices);
    const changed = Object.keys(schema).filter((k) => JSON.stringify(next.state[k]) !== JSON.stringify(state[k]));
    state = next.state;
    return changed;
  };

  return {
    root,
    view,
    controls,
    notices,
    get state() {
      return state;
    },
    /**
     * The widget's summary in words: read out (once it settles) by the live region, and given to `canvas`,
     * when passed, as its description. Widgets call it whenever what they show changes.
     * @param {string} text
     * @param {HTMLCanvasElement | null} [canvas]
     */
    describe(text, canvas) {
      describeCanvas(canvas, text);
      live.say(text);
    },
    /**
     * Builds the control panel and returns the widget's update(partial): validate, refresh the panel, let the
     * widget react to the changed keys, tell the host. The GUI, code and the URL all come in through it.
     * @param {object} hooks
     * @param {string} [hooks.title]  the panel's title (also the share bar's and the print's), else the name
     * @param {(changed: string[]) => void} hooks.onChanged  the widget redraws what depends on these keys
     * @param {import('./types.js').WidgetOptions['onStateChange']} [hooks.onStateChange]  create's option
     * @returns {(partial: Partial<Record<string, unknown>>) => void}
     */
    connect({ title, onChanged, onStateChange }) {
      /** @param {Partial<Record<string, unknown>>} partial */
      const update = (partial) => {
        const changed = apply(partial);
        if (!changed.length) return;
        gui?.sync(state);
        onChanged(changed);
        formula?.show(state);
        onStateChange?.(state);
      };
      gui = createStateGui(controls, { schema, state, onChange: update, title, locked });
      formula?.link(controlElements(gui.gui, schema));
      const getLink = () => shareLink(name, schema, state);
      const choices = linkChoices(root, { name, schema, getState: () => state });
      body.before(createShareBar({ title: title ?? name, choices })); // at the top of the widget, by its panel
      unprint = registerPrintable(root, title ?? name, getLink);
      return update;
    },
    dispose() {
      unprint?.();
      formula?.dispose();
      gui?.dispose();
      live.dispose();
      root.remove();
    },
  };
}

/**
 * Shows an update's notices on the widget and sends them from its root (STATE_NOTICES: a parent frame hears them).
 * @param {HTMLElement} root
 * @param {{ show(messages: string[]): void }} area
 * @param {string[]} notices
 */
function reportNotices(root, area, notices) {
  area.show(notices);
  root.dispatchEvent(new CustomEvent(STATE_NOTICES, { bubbles: true, detail: notices }));
}

/**
 * Where the pictures' accuracy is measured (the parity page), and, folded away for developers, each math
 * function the widget calls, linked to its GLSL-vs-JS row there.
 * @param {string[]} terms
 */
function termLinks(terms) {
  const box = document.createElement('div');
  box.className = 'widget-terms';
  const p = document.createElement('p');
  p.append('How closely the GPU’s pictures follow the exact math: the ');
  p.append(Object.assign(document.createElement('a'), { href: 'parity.html', textContent: 'parity page' }));
  p.append('.');
  const names = document.createElement('details');
  names.append(Object.assign(document.createElement('summary'), { textContent: 'For developers: the functions used' }));
  const list = document.createElement('p');
  list.append('In src/math (JavaScript) and shaders/ (GLSL), each linked to its row on the parity page: ');
  terms.forEach((name, i) => {
    if (i) list.append(' · ');
    list.append(Object.assign(document.createElement('a'), { href: `parity.html#fn-${name}`, textContent: name }));
  });
  names.append(list);
  box.append(p, names);
  return box;
}
