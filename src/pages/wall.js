// wall.html: twenty 3-D widgets mounted on one page, more than the browser's cap on live WebGL contexts;
// the shared context budget (src/core/gpu/gl-budget.js) keeps every one of them drawable.
import '../styles.css';
import { mountOrExplain } from '../core/framework/widget-failure.js';
import { glBudgetStatus } from '../core/gpu/gl-budget.js';
import { stateToParams } from '../core/framework/state.js';
import { WIDGETS } from '../widgets/registry.js';

// [widget, caption, state]: every widget with a 3-D view, in a few of its states each
const TILES = [
  ['fresnel-zones', 'Fresnel over a sphere', {}],
  ['fresnel-zones', 'Zones of n·v', { mode: 'zones-nv' }],
  ['fresnel-zones', 'Zones of l·h, torus knot', { mode: 'zones-lh', shape: 'torusknot', lightTheta: 140 }],
  ['fresnel-zones', 'Gold teapot', { material: 'gold', shape: 'teapot', camera: 'perspective' }],
  ['surfaces', 'Glass', {}],
  ['surfaces', 'Gold, rough', { material: 'gold', alpha: 0.6 }],
  ['surfaces', 'Water, grazing', { material: 'water', theta: 80 }],
  ['brdf-lobe', 'GGX lobe', {}],
  ['brdf-lobe', 'Beckmann, rough, grazing light', { D: 'beckmann', alpha: 0.6, lightTheta: 75 }],
  ['brdf-lobe', 'Two BRDFs compared', { compare: true, cosine: true, lightTheta: 60, viewTheta: 20 }],
  ['ndf-explorer', 'Five NDFs at 8°', {}],
  ['ndf-explorer', 'Five NDFs at 20°', { hwhm: 20, exposure: 4 }],
  ['ndf-explorer', 'GGX against Beckmann at 3°', { hwhm: 3, D: 'ggx,beckmann', exposure: 8 }],
  ['visibility-explorer', 'Visibility terms at α 0.5', {}],
  ['visibility-explorer', 'Smooth, α 0.1', { alpha: 0.1 }],
  [
    'visibility-explorer',
    'Smith family, rough',
    { alpha: 0.9, V: 'smithGGXSeparable,smithGGXCorrelated,smithGGXCorrelatedFast' },
  ],
  ['media', 'Clean water, 5 cm', { samples: '16' }],
  ['media', 'The talk’s grid of glasses', { view: 'grid', samples: '16' }],
  ['energy', 'White furnace', {}],
  ['energy', 'White furnace, rough only', { alphas: '0.75,1.0' }],
];

const status = document.getElementById('wall-status');
const showStatus = () => {
  const s = glBudgetStatus();
  status.textContent =
    `Live WebGL contexts: ${s.held} of a budget of ${s.limit} for ${s.views} 3-D views ` +
    `(most at once so far: ${s.peak}).`;
};
// contexts are given up and taken back as the page scrolls; these events do not bubble, so listen in capture
document.addEventListener('webglcontextlost', showStatus, true);
document.addEventListener('webglcontextrestored', showStatus, true);

const wall = document.getElementById('wall');
for (const [i, [name, caption, state]] of TILES.entries()) {
  const tile = document.createElement('article');
  tile.className = 'wall-tile';
  const heading = document.createElement('h2');
  heading.textContent = `${i + 1}. ${WIDGETS[name].title}: ${caption}`;
  const slot = document.createElement('div');
  tile.append(heading, slot);
  wall.append(tile);
  const alone = Object.assign(document.createElement('a'), { className: 'wall-open', textContent: 'open alone' });
  alone.href = `embed.html?${new URLSearchParams({ w: name })}`;
  heading.append(' ', alone);
  let schema = null; // the link follows the tile's state once its widget is up (a failed tile says so in place)
  const link = (s) =>
    schema && (alone.href = `embed.html?${new URLSearchParams([['w', name], ...stateToParams(schema, s)])}`);
  const prefix = `tile${i + 1}`;
  const options = { widgets: WIDGETS, prefix, syncUrl: false, initialState: state, onStateChange: link };
  await mountOrExplain(slot, name, options, async (instance) => {
    schema = (await WIDGETS[name].load()).widget.schema; // loaded: it is up
    link(instance.getState());
  });
  showStatus();
}
