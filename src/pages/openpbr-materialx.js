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
const cell = (tag, html) => `<${tag}>${html}</${tag.split(' ')[0]}>`;

/** The random walk's column: the largest albedo error of the family's stack with the same layers, or why none. */
function walkCell(row, family) {
  if (row.layers.includes('fuzz'))
    return (
      '<td class="note">none: the walk has no fuzz. The fuzz here is against Zeltner, Burley & Chiang 2022’s ' +
      'lobe as MaterialX implements it.</td>'
    );
  const stack = family?.variants.find((v) => v.key === STACK_OF[row.layers.join(' ')]);
  return cell('td class="figure"', stack ? `${stack.error.maxAbs.toFixed(3)} (${stack.label.split(':')[0]})` : '—');
}

function rowHtml(row, family) {
  const w = row.glsl.worst;
  return (
    '<tr>' +
    cell('th scope="row"', row.label) +
    cell('td', LAYERS_TEXT[row.layers.join(' ')]) +
    cell('td class="figure"', rgb(row.glsl.maxRelative)) +
    cell('td class="figure"', rgb(row.glsl.meanRelative)) +
    cell('td class="figure"', `${w.thetaL}°, ${w.thetaV}°, ${w.phiV}° (${w.channel})`) +
    cell('td class="figure"', row.withTurquin ? percent(row.withTurquin.worst.relative) : '—') +
    walkCell(row, family) +
    '</tr>'
  );
}

/** The velvet's figure beside its base's alone: the base's difference, not the fuzz's (when both were measured). */
function velvetWords(rows) {
  const [velvet, base] = ['velvet', 'velvet-base'].map((name) => rows.find((r) => r.name === name));
  if (!velvet || !base?.withTurquin) return '';
  return (
    ` The velvet’s ${percent(velvet.glsl.worst.relative)} is its rough base’s: without the fuzz the base differs by ` +
    `${percent(base.glsl.worst.relative)}, and by ${percent(base.withTurquin.worst.relative)} with the ` +
    'compensation put in; its fuzz lobe is MaterialX’s own fit of the paper’s tables, which the app uses too.'
  );
}

/** The section's words: what is compared, how, and why the two differ where they do on purpose. */
function introHtml(part) {
  const grazing = Math.min(...part.rows.map((r) => r.glsl.worst.thetaV));
  const mirrored = part.rows.every((r) => r.glsl.worst.phiV === 180) ? ', toward the light’s mirror direction' : '';
  return (
    '<h3>Against the reference shader: MaterialX’s OpenPBR Surface</h3>' +
    '<p class="domain">OpenPBR’s reference implementation is MaterialX’s node graph <code>open_pbr_surface</code>. ' +
    `Its own GLSL (written by MaterialX ${part.materialx}’s shader generator) and this app’s shader both ran in ` +
    `the browser under one directional light at ${part.lightsDeg.join('°, ')}° from the normal, seen from ` +
    `${part.views} directions (0° to 85° from the normal, 0° to 180° around it), for the material lab’s presets ` +
    'and one material built up layer by layer. The MaterialX columns are the difference of this app’s radiance ' +
    'from MaterialX’s, per colour channel, <strong>relative</strong> to MaterialX’s value (a near-black sample ' +
    `counts against ${part.floor * 100} % of the material’s brightest one): relative, because the materials ` +
    'range from near-black velvet to a gold highlight. The random-walk column is the largest error of the ' +
    'directional albedo (a fraction of the light, 0 to 1, not a percentage) of the stack with the same layers, ' +
    'against light followed through the layers: the family’s table above, over its cases, not these materials. ' +
    `Measured ${part.date.slice(0, 10)}.</p>` +
    '<p>Most of the difference is deliberate. This app’s lobes scatter once, as in the talk; MaterialX adds ' +
    'Turquin’s (2019) multiple-scattering compensation, which brightens rough surfaces and metals. The column ' +
    '“with Turquin’s compensation” puts it into the catalogue’s terms (for the uncoated, isotropic materials: ' +
    'brushed aluminium is anisotropic) and leaves what else differs, mostly MaterialX’s fitted albedo against ' +
    `this app’s exact one.${velvetWords(part.rows)} The largest differences are all at grazing views ` +
    `(θv ${grazing}° and beyond)${mirrored}.</p>`
  );
}

/** The section (an element): its words and its table in a scroll box of its own, named. */
export function materialxSection(part, family) {
  const section = document.createElement('div');
  section.className = 'materialx-comparison';
  const head = [
    'Material',
    'Layers',
    'vs MaterialX: largest, r / g / b',
    'vs MaterialX: mean, r / g / b',
    'largest at θl, θv, φv',
    'with Turquin’s compensation: largest',
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
