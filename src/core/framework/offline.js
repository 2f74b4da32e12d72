// Offline: every page registers the service worker that vite-plugin-pwa (Workbox) builds, which keeps every page,
// widget chunk, environment and exercise of the build on the device after one visit. When a new deploy is found,
// its files are fetched into the cache while the old version keeps running, and the page says so with a button
// to switch. Frames (embeds in a gallery or a deck) and the widget-only embed page register it too but say
// nothing: a notice there would sit on the widget itself. Added to every page by vite.config.js.
import { registerSW } from 'virtual:pwa-register';

const READY_SHOWN_MS = 8000;

function say(text, action) {
  if (window.parent !== window || document.body.classList.contains('embed')) return;
  document.querySelector('.offline-status')?.remove();
  const box = document.createElement('div');
  box.className = 'offline-status';
  box.setAttribute('role', 'status');
  box.append(Object.assign(document.createElement('span'), { textContent: text }));
  if (action) {
    const button = Object.assign(document.createElement('button'), { type: 'button', textContent: action.label });
    button.addEventListener('click', action.run);
    box.append(button);
  } else {
    setTimeout(() => box.remove(), READY_SHOWN_MS);
  }
  document.body.append(box);
}

const updateSW = registerSW({
  immediate: true,
  onOfflineReady: () => say('Shading Lab is saved on this device: every page works offline from now on.'),
  onNeedRefresh: () => {
    const reload = { label: 'Reload to use it', run: () => updateSW(true) };
    say('A new version of Shading Lab is saved on this device.', reload);
  },
});
