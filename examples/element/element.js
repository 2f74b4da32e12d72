// The element example: the module from the app's build, the widget from the app's host (?lab=URL of its
// embed.html; default: the dev server of `npm run dev`).
import '../../dist/shading-lab-widget.js';

const zones = document.getElementById('zones');
zones.setAttribute('src', new URLSearchParams(location.search).get('lab') ?? 'http://localhost:5173/embed.html');
const show = (e) => (document.getElementById('now').value = e.detail.query);
zones.addEventListener('ready', show);
zones.addEventListener('change', show);
document.getElementById('weighted').addEventListener('click', async () => {
  const { query, errors } = await zones.set({ mode: 'zones-lh-weighted' });
  document.getElementById('now').value = errors.length ? errors.join(' ') : query;
});
