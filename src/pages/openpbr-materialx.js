// The performance page's OpenPBR section, its second table: the app's shader against the specification's reference
// implementation (MaterialX's open_pbr_surface, as bench/openpbr-materialx.js measures it: the report's
// `materialx` part), each material beside its stack's albedo error against the random walk of the family above.

/** The family's stack a material's layers are (the walk's figure beside it), by the layers it switches on. */
const STACK_OF = { '': 'talk', coat: 'coat', 'coat fuzz': 'fuzz', fuzz: 'fuzz' };
const LAYERS_TEXT = { '': 'base', coat: 'base + coat', 'coat fuzz': 'base + coat + fuzz', fuzz: 'base + fuzz' };

/** A relative difference as a percentage (bench/openpbr-materialx*.js write the same figures for the docs). */
export const percent = (x) => (x < 1e-4 ? '< 0.01 %' : `${(x * 100).toFixed(2)} %`);
/** Three channels' figures, r / g / b. */
export const rgb = (xs) => xs.map(percent).join(' / ');
const cell = (tag, html) => `<${tag}>${html}</${tag}>`;

/** The random walk's column: the stack's largest albedo error, or why there is none. */
function walkCell(row, family) {
  const layers = row.layers.join(' ');
  if (row.layers.includes('fuzz'))
    return 'none: the walk has no fuzz; the fuzz is measured here against Zeltner, Burley & Chiang 2022’s lobe as ' +
      'MaterialX implements it (left)';
  const stack = family?.variants.find((v) => v.key === STACK_OF[layers]);
  return stack ? `${stack.error.maxAbs.toFixed(3)} (stack “${stack.label}”)` : '—';
}

function rowHtml(row, family) {
  const w = row.glsl.worst;
  return (
    '<tr>' +
    cell('th scope="row"', row.label) +
    cell('td', LAYERS_TEXT[row.layers.join(' ')]) +
    cell('td', rgb(row.glsl.maxRelative)) +
    cell('td', rgb(row.glsl.meanRelative)) +
    cell('td', `θl ${w.thetaL}°, θv ${w.thetaV}°, φv ${w.phiV}° (${w.channel})`) +
    cell('td', row.withTurquin ? percent(row.withTurquin.worst.relative) : '—') +
    cell('td', walkCell(row, family)) +
    '</tr>'
  );
}

/** The section's words: what is compared, how, and why the two differ where they do on purpose. */
function introHtml(part) {
  const grazing = Math.min(...part.rows.map((r) => r.glsl.worst.thetaV));
  return (
    '<h3>Against the reference shader: MaterialX’s OpenPBR Surface</h3>' +
    `<p class="domain">OpenPBR’s reference implementation is MaterialX’s node graph <code>open_pbr_surface</code>. ` +
    `Its own GLSL (MaterialX ${part.materialx}’s shader generator) and this app’s shader both ran in the browser ` +
    `under one directional light at ${part.lightsDeg.join('°, ')}° from the normal, seen from ${part.views} ` +
    'directions (0° to 85° from the normal, 0° to 180° around it), for the material lab’s presets and one ' +
    'material built up layer by layer. Each column of MaterialX figures is the difference of this app’s radiance ' +
    'from MaterialX’s, per colour channel, <strong>relative</strong> to MaterialX’s value (a near-black sample ' +
    `counts against ${part.floor * 100} % of the material’s brightest one): relative, because the materials ` +
    'range from near-black velvet to a gold highlight. The random-walk column is the error of the same layers’ ' +
    'directional albedo (a fraction of the light, 0 to 1, not a percentage) against light followed through the ' +
    `layers, the family’s table above, over its cases. Measured ${part.date.slice(0, 10)}.</p>` +
    '<p>Most of the difference is deliberate. This app’s lobes scatter once, as in the talk; MaterialX adds ' +
    'Turquin’s (2019) multiple-scattering compensation, which brightens rough and metallic surfaces. The column ' +
    '“with Turquin’s compensation” puts that compensation into the catalogue’s terms (for the uncoated, ' +
    'isotropic materials) and leaves what else differs: mostly MaterialX’s fitted albedo against this app’s ' +
    `exact one. The largest differences are all at grazing views (θv ${grazing}° and beyond).</p>`
  );
}

/** The section (an element): its words and its table in a scroll box of its own, named. */
export function materialxSection(part, family) {
  const section = document.createElement('div');
  section.className = 'materialx-comparison';
  const head = [
    'Material',
    'Layers',
    'vs MaterialX: largest (r / g / b)',
    'vs MaterialX: mean (r / g / b)',
    'Largest at',
    'vs MaterialX, with Turquin’s compensation: largest',
    'vs random walk: largest albedo error',
  ];
  section.innerHTML =
    introHtml(part) +
    '<div class="table-scroll" tabindex="0" role="region" aria-label="Table: OpenPBR against MaterialX">' +
    '<table class="data-table compact" id="materialx-table">' +
    `<thead><tr>${head.map((h) => cell('th', h)).join('')}</tr></thead>` +
    `<tbody>${part.rows.map((r) => rowHtml(r, family)).join('')}</tbody></table></div>`;
  return section;
}
