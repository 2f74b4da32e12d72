// The example deck: reveal.js from npm, the plugin from the app's build (dist/), the widgets from the app's
// host, given as ?lab=URL of its embed.html (default: the dev server of `npm run dev`).
import Reveal from '../../node_modules/reveal.js/dist/reveal.mjs';
import ShadingLab from '../../dist/shading-lab-reveal.js';

const lab = new URLSearchParams(location.search).get('lab') ?? 'http://localhost:5173/embed.html';
Reveal.initialize({ hash: true, shadingLab: { src: lab }, plugins: [ShadingLab] });
