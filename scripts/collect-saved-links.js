// Collects, from a build's source tree, a saved link of each widget in the forms a user keeps: the share link
// (embed.html?w=…), the chapter page's link (its keys under the page's prefix) and the state a parent frame reads
// and sends back in an embed `set` message, each with the state that build opens it at. Run it on an old tree to
// fix what a newer build must still open (tests/support/saved-links.json, read by tests/unit/saved-links.test.js),
// with the tree's widget exercises:
//   git archive <commit> | tar -x -C /tmp/old && ln -s "$PWD/node_modules" /tmp/old/
//   node scripts/collect-saved-links.js /tmp/old <commit> > tests/support/saved-links.json
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const root = resolve(process.argv[2] ?? '.');
const load = (path) => import(pathToFileURL(join(root, path)).href);
const { coerceState, defaultState, stateToParams } = await load('src/core/framework/state.js');

/** The first page (and its prefix) whose URL carries the widget's state, from the tree's pages' `data-slot`s. */
const PAGES = {};
for (const page of readdirSync(root)
  .filter((f) => f.endsWith('.html'))
  .sort()) {
  for (const [div] of readFileSync(join(root, page), 'utf8').matchAll(/<div[^>]*data-slot="[^"]*"[^>]*>/g)) {
    const [slot, prefix] = ['slot', 'prefix'].map((a) => div.match(new RegExp(`data-${a}="([^"]*)"`))?.[1]);
    if (prefix) PAGES[slot] ??= [page, prefix];
  }
}

/** A value of field `f` other than its default, as a user could set it: every field of the link then says something. */
function otherValue(f) {
  const keys = f.options ? Object.keys(f.options) : [];
  switch (f.type) {
    case 'number': {
      const third = f.min + Math.round((f.max - f.min) / 3 / f.step) * f.step;
      return +(third !== f.default ? third : f.max).toFixed(6);
    }
    case 'enum':
      return keys.find((k) => k !== f.default);
    case 'set': {
      const pick = keys.slice(-2); // the menu's last two: `custom`, where a widget offers the user's own term
      return pick.join() === [...f.default].join() ? keys.slice(0, 1) : pick;
    }
    case 'bool':
      return !f.default;
    case 'color':
      return '#1f6e43';
    case 'samples':
      return Array.from({ length: f.length }, (_, i) => +(f.min + ((f.max - f.min) * i) / (f.length - 1)).toFixed(3));
    case 'text':
      return 'saved file.binary';
    case 'code':
      return `${f.default}\n// saved with the link\n`;
    case 'params':
      return { gain: 0.5 };
    default:
      throw new Error(`no other value for a ${f.type} field`);
  }
}

/** The links of one widget in state `input`: the state the tree opens them at, and each form. */
function linksOf(name, schema, input, what) {
  const { state, notices } = coerceState(schema, input);
  if (notices.length) throw new Error(`${name} (${what}): ${notices.join(' ')}`);
  const params = stateToParams(schema, state);
  const links = [
    { widget: name, what, form: 'share', link: `embed.html?${new URLSearchParams([['w', name], ...params])}` },
  ];
  if (PAGES[name]) {
    const [page, prefix] = PAGES[name];
    const query = new URLSearchParams([...params].map(([k, v]) => [`${prefix}.${k}`, v]));
    links.push({ widget: name, what, form: 'page', link: `${page}?${query}`, prefix });
  }
  links.push({ widget: name, what, form: 'set', message: { type: 'shading-lab:set', state } });
  return links.map((l) => ({ ...l, state }));
}

/** Links by hand, as the old tree's pages, tour and pictures wrote them, beside the every-field ones. */
const BY_HAND = {
  'ndf-explorer': [{ hwhm: 12, ndfs: ['ggx', 'beckmann'] }],
  'visibility-explorer': [{ alpha: 0.9, lightTheta: 60, terms: ['implicit', 'smithGGXCorrelated'] }],
  'diffuse-explorer': [{ models: ['lambert', 'orenNayar'], sigma: 60 }],
  'material-lab': [
    { material: 'custom', diffuse: '#ffffff', layers: 'diffuse', diffuseModel: 'oren-nayar', sigma: 30 },
    { fresnel: 'one', ndf: 'beckmann', visibility: 'kelemen', compensation: 'kullaConty', alpha: 0.6 },
  ],
  'lighting-models': [{ material: 'custom', diffuse: '#2a6f9e', f0: 0.5 }],
  'fresnel-curves': [{ materials: ['custom', 'gold'], ior: 1.7 }],
};

/** Where the first other option opens no view: a measured BRDF needs a dropped file, which no link carries. */
const OTHER = { 'material-lab': { brdfSource: 'custom' } };

const links = [];
const names = readdirSync(join(root, 'src/widgets')).filter((d) =>
  existsSync(join(root, 'src/widgets', d, 'schema.js')),
);
for (const name of names.sort()) {
  const { schema } = await load(`src/widgets/${name}/schema.js`);
  const every = { ...Object.fromEntries(Object.entries(schema).map(([k, f]) => [k, otherValue(f)])), ...OTHER[name] };
  links.push(
    ...linksOf(name, schema, defaultState(schema), 'defaults'),
    ...linksOf(name, schema, every, 'every field'),
  );
  (BY_HAND[name] ?? []).forEach((input, i) => links.push(...linksOf(name, schema, input, `by hand ${i + 1}`)));
}
// the widget exercises a lecturer may have copied and shared (their state and locked keys are widget state too)
const dir = join(root, 'public/exercises');
const exercises = readdirSync(dir)
  .filter((f) => f.endsWith('.json') && f !== 'index.json')
  .sort()
  .map((f) => JSON.parse(readFileSync(join(dir, f), 'utf8')))
  .filter((e) => e.widget);
process.stdout.write(`${JSON.stringify({ from: process.argv[3] ?? root, links, exercises }, null, 1)}\n`);
