// Share a widget's exact state: a link and the link's QR code, large enough to project so a class can open it on
// their phones. On a page whose URL carries the widget's state (a chapter) the link is, by default, to the page at
// this state, scrolled to the widget, with the text around it; the dialog also offers the widget alone
// (embed.html with its state), for slides. Elsewhere (the tour, an exercise, the embed itself) only the widget
// alone. A modal <dialog>: focus moves into it, Esc or Close leaves it, and focus goes back to the Share button.
// The QR code is drawn here (npm qrcode, loaded when first needed), no network.
import { stateToParams } from './state.js';
import { urlWithState } from './widget-host.js';

const QR_PIXELS = 560; // drawn size; shown at up to min(70vmin, 560px, 100vh − room for the rest of the dialog)

/** The link to widget `name` alone in `state`, relative to the page at `base`. */
export function shareLink(name, schema, state, base = location.href) {
  const url = new URL('embed.html', base);
  url.search = new URLSearchParams([['w', name], ...stateToParams(schema, state)]).toString();
  return url.href;
}

/**
 * The link to the page `href` with the widget's state in it (under `prefix`) and `anchor` (the widget's section)
 * as its hash.
 */
export function pageLink(href, schema, state, prefix, anchor) {
  const url = urlWithState(href, schema, state, prefix);
  if (anchor) url.hash = anchor;
  return url.href;
}

/** What a link is to, in the words of the Share button and the dialog's choice. */
export const LINK_WORDS = {
  page: { button: 'Share: this chapter at this state', choice: 'this chapter, at this state, at this widget' },
  widget: { button: 'Share: this widget', choice: 'this widget alone, at this state (for slides)' },
};

/**
 * The choices of links for the widget `root`: the page's, when its host keeps the widget's state in the page's URL
 * and the page is not the widget alone, then the widget's. Each is { kind, get() }.
 */
export function linkChoices(root, { name, schema, getState }) {
  const widget = { kind: 'widget', get: () => shareLink(name, schema, getState()) };
  const host = /** @type {HTMLElement | null} */ (root.closest('[data-state-in-url]'));
  if (!host || new URL(location.href).pathname === new URL(widget.get()).pathname) return [widget];
  const anchor = root.closest('section[id]')?.id ?? '';
  const prefix = host.dataset.stateInUrl ?? '';
  return [{ kind: 'page', get: () => pageLink(location.href, schema, getState(), prefix, anchor) }, widget];
}

function el(tag, props = {}, ...children) {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}

/** Radio buttons, one per choice of link; `onPick(choice)` when one is picked. */
function choicePicker(choices, onPick) {
  const group = `share-choice-${Date.now()}`;
  const fieldset = el('fieldset', { className: 'share-choices' }, el('legend', { textContent: 'Link to' }));
  choices.forEach((choice, i) => {
    const input = el('input', { type: 'radio', name: group, value: choice.kind, checked: i === 0 });
    input.addEventListener('change', () => input.checked && onPick(choice));
    fieldset.append(el('label', {}, input, ` ${LINK_WORDS[choice.kind].choice}`));
  });
  return fieldset;
}

/** Opens the share dialog for `choices` (the first the default); `opener` gets the focus back when it closes. */
export async function openShareDialog(title, choices, opener) {
  const heading = el('h2', { id: `share-title-${Date.now()}`, textContent: `Share: ${title}` });
  const qr = el('canvas', { className: 'share-qr' });
  qr.setAttribute('role', 'img');
  const field = el('input', { type: 'text', readOnly: true, className: 'share-link' });
  const status = el('span', { className: 'share-status', role: 'status' });
  const copy = el('button', { type: 'button', textContent: 'Copy link' });
  const close = el('button', { type: 'button', textContent: 'Close', className: 'share-close' });
  const show = async (choice) => {
    const link = choice.get();
    const words = LINK_WORDS[choice.kind].choice;
    field.value = link;
    field.setAttribute('aria-label', `Link to ${words}`);
    qr.setAttribute('aria-label', `QR code of the link to ${words}: ${title}`);
    status.textContent = '';
    const { default: QRCode } = await import('qrcode');
    await QRCode.toCanvas(qr, link, { width: QR_PIXELS, margin: 2, errorCorrectionLevel: 'M' });
  };
  const dialog = el(
    'dialog',
    { className: 'share-dialog' },
    heading,
    el('p', { textContent: 'Scan the code to open it on a phone, or copy the link.' }),
    ...(choices.length > 1 ? [choicePicker(choices, show)] : []),
    qr,
    el('p', { className: 'share-row' }, field, copy, status),
    close,
  );
  dialog.setAttribute('aria-labelledby', heading.id);
  copy.addEventListener('click', async () => {
    field.select();
    try {
      await navigator.clipboard.writeText(field.value);
      status.textContent = 'Copied.';
    } catch {
      status.textContent = 'Selected: press Ctrl+C (⌘C) to copy.';
    }
  });
  close.addEventListener('click', () => dialog.close());
  dialog.addEventListener('close', () => {
    dialog.remove();
    opener?.focus();
  });
  document.body.append(dialog);
  dialog.showModal();
  close.focus();
  await show(choices[0]);
  dialog.dataset.ready = '';
  return dialog;
}

/** A bar with the widget's Share button, which names what its link is to; the links are made on each press. */
export function createShareBar({ title, choices }) {
  const words = LINK_WORDS[choices[0].kind];
  const button = el('button', { type: 'button', className: 'share-button', textContent: words.button });
  button.addEventListener('click', () => openShareDialog(title, choices, button));
  return el('div', { className: 'widget-share' }, button);
}
