// fresnel-zones, in words: the about text, the legend's lines and the picture described for screen readers.
import { declareFormula, texNumber } from '../../core/framework/formula-registry.js';
import { ZONE_LABELS, paletteColourNames } from '../../core/ui/palettes.js';
import { fresnelParams, materialByKey } from '../../math/materials.js';
import { MODES, SHAPES } from './schema.js';
import { AVERAGE_LIGHTS, isWeighted, zonesByLh } from './model.js';

export const TITLE = 'Fresnel zones';

export const ABOUT =
  'In the modes of l·h, drag on the picture (or focus it and use the arrow keys) to move the light; the ring ' +
  'marks light at 90° from the view. n·v depends on the viewer alone, so its modes hide the light. Start with ' +
  'the glass Fresnel of n·v: dark centre, bright rim, the zones’ borders drawn on it. Then compare the zones of ' +
  'n·v with the zones of l·h: by l·h the whole object can turn yellow or red, yet once weighted by the rest of the ' +
  'BRDF the light that actually reaches the eye is mostly green. Hover the surface to probe it. While the light ' +
  'moves, edges are drawn without smoothing so that the picture keeps up; they are smoothed once it stops.';

const pct = (x) => `${(x * 100).toFixed(1)}%`;
/** A zone's short name: 'barely changes', … */
export const zoneName = (i) => ZONE_LABELS[i].split(' (')[0];
const zoneList = (shares) => shares.map((z, i) => `${zoneName(i)} ${pct(z)}`).join(', ');
const shareOf = (state) => (isWeighted(state) ? 'reflected light' : 'covered pixels');
const angleName = (state) => (zonesByLh(state) ? 'l·h' : 'n·v');

/** The legend's heading: what is shared out, by which angle, and whether the figures in brackets are exact. */
export const legendHead = (state, analytic) =>
  `Zones of ${angleName(state)}${state.mode === 'fresnel-nv' ? ', their borders drawn as lines on the picture' : ''}` +
  ` — share of ${shareOf(state)}${analytic ? ' (analytic for this sphere)' : ''}`;

/** One zone's measured share, and its exact share in brackets where known. */
export const shareText = (share, exact) => `${pct(share)}${exact === undefined ? '' : ` (${pct(exact)})`}`;

export const averageText = (state, averageShares) =>
  `Averaged over ${AVERAGE_LIGHTS} light directions all around the object (GGX α ${state.alpha}): ` +
  `${zoneList(averageShares)}.`;

function pictureText(state) {
  if (state.mode === 'fresnel-nv') {
    const f0 = fresnelParams(state.material, state.conductor).f0;
    return (
      `${state.fresnel} Fresnel reflectance of n·v: ${f0.map(pct).join(' / ')} where the surface faces the ` +
      'viewer, rising to 100% at the silhouette; the zones of n·v outlined at 45° and 75°'
    );
  }
  const alpha = isWeighted(state) ? ` (GGX α ${state.alpha})` : '';
  return `${MODES[state.mode]}${alpha}, zones coloured ${paletteColourNames(state.palette)}`;
}

/** The picture in words: the shape, what colours it, where the light is, and the measured zone shares. */
export function describeView(state, { zoneShares, averageShares }) {
  const light = `${state.lightTheta.toFixed(0)}° from the view direction, ${state.lightPhi.toFixed(0)}° around it`;
  const behind = state.lightTheta > 90 ? ' (behind the object)' : '';
  const average =
    averageShares && isWeighted(state)
      ? ` Averaged over ${AVERAGE_LIGHTS} light directions: ${zoneList(averageShares)}.`
      : '';
  return (
    `${SHAPES[state.shape]} (${state.camera}), ${materialByKey(state.material).name}: ${pictureText(state)}. ` +
    `Light ${light}${behind}. ` +
    `Share of ${shareOf(state)} by zone of ${angleName(state)}: ${zoneList(zoneShares)}.${average}`
  );
}

const deg = (x) => `${texNumber(x, 0)}^\\circ`;
const zoneOf = (angle) =>
  `${angle} < 45^\\circ,\\quad 45^\\circ \\le ${angle} < 75^\\circ,\\quad ${angle} \\ge 75^\\circ`;

/** Fresnel of n·v as the picture shades it: exact from the material's n (and k), or Schlick from its F0. */
function fresnelNv(state) {
  const p = fresnelParams(state.material, state.conductor);
  const f0 = p.metal ? `(${p.f0.map((x) => texNumber(x)).join(',\\ ')})` : texNumber(p.f0[0]);
  const name = `\\sym{material}{\\text{${materialByKey(state.material).name}}}`;
  const F =
    state.fresnel === 'schlick'
      ? '\\sym{fresnel}{F_{\\text{Schlick}}}(\\mathbf{n},\\mathbf{v}) = F_0 + (1 - F_0)(1 - \\nv )^5'
      : '\\sym{fresnel}{F_{\\text{exact}}}(\\mathbf{n}\\cdot\\mathbf{v};\\ n, k)';
  return `${F},\\quad F_0 = ${f0}\\ (${name})`;
}

/** The light as the sliders place it, from the view. */
const lightAt = (state) =>
  `\\mathbf{l}:\\ \\theta = \\sym{lightTheta}{${deg(state.lightTheta)}},\\ \\phi =` +
  ` \\sym{lightPhi}{${deg(state.lightPhi)}}`;

/** The formula behind each mode: Fresnel of n·v, the zones of an angle, or l·h zones weighted by the BRDF. */
export const FORMULA = declareFormula('fresnel-zones', (state) => {
  if (state.mode === 'fresnel-nv') return fresnelNv(state);
  if (state.mode === 'zones-nv') return `\\theta = \\arccos\\nv :\\quad ${zoneOf('\\theta')}`;
  const zones = `\\theta_d = \\arccos\\lh :\\quad ${zoneOf('\\theta_d')}`;
  if (!isWeighted(state)) return `\\begin{gathered}${zones}\\\\ ${lightAt(state)}\\end{gathered}`;
  const a = `\\sym{alpha}{${texNumber(state.alpha, 2)}}`;
  const weight =
    `\\text{weight} = \\pi\\,\\frac{D_{\\text{GGX}}(\\mathbf{h})\\,V_{\\text{Smith}}(\\mathbf{l},\\mathbf{v})}{4}` +
    `\\,\\nl ,\\quad \\alpha = ${a}`;
  return `\\begin{gathered}${zones}\\\\ ${weight}\\\\ ${lightAt(state)}\\end{gathered}`;
});
