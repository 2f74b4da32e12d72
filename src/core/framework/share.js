// Share a widget's exact state: a link to it alone (embed.html with its state) and the link's QR code, large
// enough to project so a class can open it on their phones. A modal <dialog>: focus moves into it, Esc or
// Close leaves it, and focus goes back to the Share button. The QR code is drawn here (npm qrcode, loaded
// when first needed), no network.
import { stateToParams } from './state.js';

const QR_PIXELS = 560; // drawn size; shown at up to min(70vmin, 560px)

/** The link to widget `name` alone in `state`, relative to the page at `base`. */
export function shareLink(name, schema, state, base = location.href) {
  const url = new URL('embed.html', base);
  url.search = new URLSearchParams([['w', name], ...stateToParams(schema, state)]).toString();
  return url.href;
}

function el(tag, props = {}, ...children) {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}

/** Opens the share dialog for `link`; `opener` gets the focus back when it closes. */
export async function openShareDialog(title, link, opener) {
  const heading = el('h2', { id: `share-title-${Date.now()}`, textContent: `Share: ${title}` });
  const qr = el('canvas', { className: 'share-qr' });
  qr.setAttribute('role', 'img');
  qr.setAttribute('aria-label', `QR code of the link to this state of ${title}`);
  const field = el('input', { type: 'text', readOnly: true, value: link, className: 'share-link' });
  field.setAttribute('aria-label', 'Link to this state');
  const status = el('span', { className: 'share-status', role: 'status' });
  const copy = el('button', { type: 'button', textContent: 'Copy link' });
  const close = el('button', { type: 'button', textContent: 'Close', className: 'share-close' });
  const dialog = el(
    'dialog',
    { className: 'share-dialog' },
    heading,
    el('p', { textContent: 'Scan the code to open this exact state on a phone, or copy the link.' }),
    qr,
    el('p', { className: 'share-row' }, field, copy, status),
    close,
  );
  dialog.setAttribute('aria-labelledby', heading.id);
  copy.addEventListener('click', async () => {
    field.select();
    try {
      await navigator.clipboard.writeText(link);
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
  const { default: QRCode } = await import('qrcode');
  await QRCode.toCanvas(qr, link, { width: QR_PIXELS, margin: 2, errorCorrectionLevel: 'M' });
  dialog.dataset.ready = '';
  return dialog;
}

/** A bar with the widget's Share button: getLink() is called on each press (the state then). */
export function createShareBar({ title, getLink }) {
  const button = el('button', { type: 'button', className: 'share-button', textContent: 'Share' });
  button.title = 'A link and a QR code to this exact state';
  button.addEventListener('click', () => openShareDialog(title, getLink(), button));
  return el('div', { className: 'widget-share' }, button);
}
