// Offline: every page registers the service worker that vite-plugin-pwa (Workbox) builds, which keeps every page,
// widget chunk, environment and exercise of the build on the device after one visit. When a new deploy is found,
// its files are fetched into the cache while the old version keeps running, and the page says so with a button
// to switch. Frames (embeds in a gallery or a deck) and the widget-only embed page register it too but say
// nothing: a notice there would sit on the widget itself. Added to every page by vite.config.js.
import { registerSW } from 'virtual:pwa-register';
import { publish } from './debug-hooks.js';

const SAVED_SEEN_KEY = 'shading-lab:offline-ready-seen'; // the first visit's "saved" is said once per device

/** Whether `key` is set in localStorage; sets it. Storage refused (a private window's quota): said each time. */
function firstTime(key) {
  try {
    if (localStorage.getItem(key)) return false;
    localStorage.setItem(key, '1');
  } catch {
    /* no storage: nothing remembers that it was said */
  }
  return true;
}

/**
 * Says `text` in the site header, in the page's flow above the content (so it covers nothing), with a Dismiss
 * button and, when given, an action. Pages without the header (none but embed's) get it at the top of the body.
 * @param {string} text
 * @param {{ label: string, run: () => void }} [action]
 */
function say(text, action) {
  if (window.parent !== window || document.body.classList.contains('embed')) return;
  document.querySelector('.offline-status')?.remove();
  const box = document.createElement('div');
  box.className = 'offline-status';
  box.setAttribute('role', 'status');
  box.append(Object.assign(document.createElement('span'), { textContent: text }));
  const button = (label, run) => {
    const b = Object.assign(document.createElement('button'), { type: 'button', textContent: label });
    b.addEventListener('click', run);
    return b;
  };
  if (action) box.append(button(action.label, action.run));
  box.append(button('Dismiss', () => box.remove()));
  const header = document.querySelector('.site-header');
  if (header) header.append(box);
  else document.body.prepend(box);
}

const updateSW = registerSW({
  immediate: true,
  onOfflineReady: () => {
    const announced = firstTime(SAVED_SEEN_KEY);
    if (announced) say('Shading Lab is saved on this device: every page works offline from now on.');
    publish('offline', { ready: true, announced });
  },
  onNeedRefresh: () => {
    const reload = { label: 'Reload to use it', run: () => updateSW(true) };
    say('A new version of Shading Lab is saved on this device.', reload);
  },
});
