// The guided tour: the talk's ideas one step at a time, each with the widget that shows it set up for it.
// Every step has its own URL (tour.html#<step id>), so a slide can link to it and the browser's back and
// forward walk the tour. A widget that goes on from one step to the next is kept and only given the new
// state; a different one replaces it, and the old one is disposed (its WebGL context with it).
import '../styles.css';
import { mountOrExplain } from '../core/framework/widget-failure.js';
import { publish } from '../core/framework/debug-hooks.js';
import { defaultState, showValue } from '../core/framework/state.js';
import { createNoticeArea } from '../core/framework/notice.js';
import { WIDGETS, isWidgetName } from '../widgets/registry.js';
import { tourPlan } from '../tour/steps.js';
import { hashId } from '../core/framework/url-hash.js';
import { setInlineTex } from '../core/ui/inline-tex.js';
import { typesetFormulas } from '../core/framework/formulas.js';

const { steps, sections } = tourPlan(isWidgetName);
const root = document.getElementById('tour');
const $ = (selector) => root.querySelector(selector);
const stage = $('.tour-stage');
const notices = createNoticeArea($('.tour-messages'));
const [prevButton, nextButton, fullscreenButton] = ['.tour-prev', '.tour-next', '.tour-fullscreen'].map($);

renderSections();

let index = -1; // the step shown, or being set up
let mounted = null; // { name, instance }
let queue = Promise.resolve(); // steps are set up one after another; only the latest request is shown

function show(i) {
  index = i;
  renderText(steps[i], i);
  publish('tour', { index: i, id: steps[i].id, ready: false });
  queue = queue
    .then(() => (i === index ? setUp(steps[i], i) : null))
    .catch((err) => notices.show(`This step could not be set up: ${err.message}`));
  return queue;
}

async function setUp(step, i) {
  if (mounted?.name === step.widget) {
    const { widget } = await WIDGETS[step.widget].load(); // loaded already: it is up
    mounted.instance.update({ ...defaultState(widget.schema), ...step.state }); // the same picture as a fresh one
  } else {
    if (mounted) release(mounted.instance);
    mounted = null;
    stage.replaceChildren();
    // a widget that fails says so on the stage with Retry; a retry that works is this step's widget
    const up = (instance) => (mounted = { name: step.widget, instance });
    const options = { widgets: WIDGETS, prefix: 'tour', syncUrl: false, initialState: step.state };
    if (!(await mountOrExplain(stage, step.widget, options, up))) return;
  }
  if (i !== index) return;
  bringIntoSight(step);
  publish('tour', { index: i, id: step.id, widget: step.widget, instance: mounted.instance, ready: true });
}

/**
 * Where the step's head (its buttons and words) stays on screen while the widget scrolls under it (a wide,
 * tall enough window: styles.css), scrolls the view the step speaks of (`look`), or else the widget's top, to
 * just below the head; a step's words then always sit above the picture they describe. A phone keeps the page
 * as the reader left it.
 */
function bringIntoSight(step) {
  const head = $('.tour-head');
  if (getComputedStyle(head).position !== 'sticky') return;
  const target = (step.look && stage.querySelector(step.look)) || stage;
  const gap = target.getBoundingClientRect().top - head.offsetHeight - 8; // the head, once stuck, is at the top
  // the widget's top is only brought back when the reader had scrolled past it
  if (target !== stage || gap < 0) (document.fullscreenElement ?? document.scrollingElement).scrollBy(0, gap);
}

/**
 * Disposes a widget and gives its WebGL contexts back at once: a disposed renderer's context otherwise lives
 * until garbage collection, and a long tour would run into the browser's limit on live contexts.
 */
function release(instance) {
  // getContext returns the context a canvas already has
  const contexts = [...stage.querySelectorAll('.viewport canvas')].map((c) => c.getContext('webgl2'));
  instance.dispose();
  for (const gl of contexts) gl?.getExtension('WEBGL_lose_context')?.loseContext();
}

function renderText(step, i) {
  const section = sections.find((s) => s.key === step.section);
  $('.tour-count').textContent = `Step ${i + 1} of ${steps.length}`;
  $('.tour-section').textContent =
    `${sections.indexOf(section) + 1}. ${section.title} (${i - section.first + 1} of ${section.count})`;
  $('.tour-title').textContent = step.title;
  $('.tour-spoken-title').textContent = `: ${step.title}`; // the live progress line reads the new title too
  setInlineTex($('.tour-text'), step.text);
  typesetFormulas($('.tour-text'));
  const meter = $('.tour-meter');
  meter.max = steps.length;
  meter.value = i + 1;
  const coming = sections.filter((s) => !s.count).map((s) => s.title);
  const end = $('.tour-end');
  end.hidden = i !== steps.length - 1;
  end.textContent = `End of the tour${coming.length ? ` so far. Still to come: ${coming.join(', ')}` : ''}.`;
  prevButton.setAttribute('aria-disabled', String(i === 0));
  nextButton.setAttribute('aria-disabled', String(i === steps.length - 1));
  const list = $('.tour-sections ol');
  for (const li of list.children) {
    if (li.dataset.section !== step.section) li.removeAttribute('aria-current');
    else {
      li.setAttribute('aria-current', 'step');
      list.scrollLeft = li.offsetLeft - list.offsetLeft - 8; // a phone's one row of sections: the current one in sight
    }
  }
  document.title = `${step.title} — Guided tour — Shading Lab`;
}

/** The talk's sections: a link to the first step of each, or "coming" where there is none yet. */
function renderSections() {
  $('.tour-sections ol').replaceChildren(
    ...sections.map((s) => {
      const li = document.createElement('li');
      li.dataset.section = s.key;
      if (s.count)
        li.append(Object.assign(document.createElement('a'), { href: `#${steps[s.first].id}`, textContent: s.title }));
      else {
        li.className = 'coming';
        li.append(
          s.title,
          ' ',
          Object.assign(document.createElement('span'), { className: 'tag', textContent: 'coming' }),
        );
      }
      return li;
    }),
  );
}

/** Moves to step i; the URL changes with a history entry, and the hashchange shows the step. */
function go(i) {
  const j = Math.min(Math.max(i, 0), steps.length - 1);
  if (j !== index) location.hash = steps[j].id;
}

function route() {
  const id = hashId();
  const i = steps.findIndex((s) => s.id === id);
  if (i >= 0) {
    if (i !== index) show(i);
    return;
  }
  const keep = Math.max(index, 0);
  const where = `${index >= 0 ? 'stayed on' : 'showing'} “${steps[keep].title}”`;
  if (id) notices.show(`There is no step ${showValue(id)} in the tour; ${where}.`);
  history.replaceState(history.state, '', `#${steps[keep].id}`);
  if (index < 0) show(keep);
}

// Keys: a control that has the focus keeps its own (sliders, inputs, lists; a canvas that moves a light or a
// plot cursor marks the keys it used with preventDefault); everything else drives the tour.
const NEXT = new Set(['ArrowRight', 'PageDown', ' ']);
const PREVIOUS = new Set(['ArrowLeft', 'PageUp']);
const typingIn = (el) =>
  el instanceof Element &&
  (el.isContentEditable || el.matches('input, select, textarea, [role=slider], [role=spinbutton]'));
window.addEventListener('keydown', (e) => {
  if (e.defaultPrevented || e.altKey || e.ctrlKey || e.metaKey || typingIn(e.target)) return;
  const pressable = e.target instanceof Element && e.target.closest('button, a, summary, [role=button]');
  if (e.key === ' ' && pressable) return; // Space presses it
  const to = NEXT.has(e.key)
    ? index + 1
    : PREVIOUS.has(e.key)
      ? index - 1
      : e.key === 'Home'
        ? 0
        : e.key === 'End'
          ? steps.length - 1
          : null;
  if (to !== null) {
    e.preventDefault();
    go(to);
  } else if (e.key === 'f' || e.key === 'F') {
    e.preventDefault();
    toggleFullscreen();
  }
});
// Escape hands the keys back to the tour from inside the widget (lil-gui keeps its keys from bubbling)
window.addEventListener(
  'keydown',
  (e) => {
    if (e.key === 'Escape' && stage.contains(document.activeElement)) document.activeElement.blur();
  },
  true,
);

prevButton.addEventListener('click', () => go(index - 1));
nextButton.addEventListener('click', () => go(index + 1));
fullscreenButton.addEventListener('click', toggleFullscreen);

async function toggleFullscreen() {
  if (document.fullscreenElement) return document.exitFullscreen();
  try {
    if (!document.fullscreenEnabled) throw new Error('full screen is not enabled');
    await root.requestFullscreen();
  } catch {
    notices.show(
      'The browser did not allow full screen here (a frame or a setting may forbid it). Use the browser’s own ' +
        'full-screen key instead, usually F11.',
    );
  }
}
document.addEventListener('fullscreenchange', () => {
  fullscreenButton.textContent = document.fullscreenElement ? 'Exit full screen' : 'Full screen';
});

window.addEventListener('hashchange', route);
route();
