// @ts-check
// A widget that fails to load (its chunk aborted: a flaky network, a redeploy under an open page) or to start (an
// exception in its create, or in a library's module) is kept in its own box: its place says what failed and offers
// Retry, and the page's other widgets still mount. Pages mount through mountOrExplain, never mountWidget directly.
import { mountWidget } from './widget-host.js';

/** @typedef {import('./types.js').Widget} Widget */
/** @typedef {import('./widget-host.js').MountOptions} MountOptions */

/**
 * What went wrong, in words for the reader: a chunk that did not arrive reads differently from a bug.
 * @param {unknown} err
 */
export function describeFailure(err) {
  const message = err instanceof Error ? err.message : String(err);
  const missing = /dynamically imported module|Importing a module script failed|error loading dynamically/i;
  if (missing.test(message) || /preload/i.test(message))
    return {
      what: 'did not arrive',
      why:
        'Part of the app was not downloaded (the network, or a new version ' +
        'of the site replaced it while this page was open).',
      detail: message,
    };
  return { what: 'could not start', why: 'It stopped with an error while setting up.', detail: message };
}

/**
 * Removes what a failed create left in the container (its canvases, GUI) and puts the failure box there.
 * @param {HTMLElement} container
 * @param {Set<Node>} before  the container's children before the attempt
 * @param {string} title
 * @param {unknown} err
 * @param {() => void} retry
 */
function showFailure(container, before, title, err, retry) {
  for (const child of [...container.childNodes]) if (!before.has(child)) child.remove();
  const { what, why, detail } = describeFailure(err);
  const box = document.createElement('div');
  box.className = 'blocking-message widget-failure';
  box.setAttribute('role', 'alert');
  const head = document.createElement('strong');
  head.textContent = `${title} ${what}.`;
  const text = document.createElement('p');
  text.textContent =
    `${why} The rest of the page is unaffected. Retry loads it again; reloading the page also ` +
    'keeps what the other widgets show (their state is in the address).';
  const code = document.createElement('p');
  code.className = 'widget-failure-detail';
  code.textContent = detail;
  const button = document.createElement('button');
  button.type = 'button';
  button.textContent = 'Retry';
  button.addEventListener('click', () => {
    box.remove();
    retry();
  });
  box.append(head, text, code, button);
  container.append(box);
  return box;
}

/**
 * Mounts widget `name` like mountWidget; if it fails, shows why in `container` with a Retry button and resolves
 * null. `onMount` hears of every instance that comes up, the first try's or a retry's, so a page that wires
 * widgets together can pick up one that arrived late; it is handed the widget's module too (its schema: what
 * the embed protocol checks a parent's keys against), so nothing loads it a second time.
 * @param {HTMLElement} container
 * @param {string} name
 * @param {MountOptions} options
 * @param {(instance: Widget, widget: import('./types.js').WidgetContract) => void} [onMount]
 * @returns {Promise<Widget | null>}
 */
export async function mountOrExplain(container, name, options, onMount) {
  const before = new Set(container.childNodes);
  try {
    const { instance, widget } = await mountWidget(container, name, options);
    onMount?.(instance, widget);
    return instance;
  } catch (err) {
    console.warn(`Shading Lab: widget ${name} failed:`, err); // the page says it too; this keeps the stack
    const title = options.widgets[name]?.title ?? name;
    showFailure(container, before, title, err, () => void mountOrExplain(container, name, options, onMount));
    return null;
  }
}
