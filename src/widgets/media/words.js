// media, in words: the about text, the readout under the picture and the picture described for screen readers.
import { rgbToHex } from '../../core/ui/palettes.js';
import { linearToSrgb } from '../../math/color.js';
import { MEDIA } from './schema.js';
import { extinction, unscattered } from './model.js';
import { declareFormula, texNumber, texSignificant } from '../../core/framework/formula-registry.js';

export const TITLE = 'Media';

export const ABOUT =
  'The depth slider runs from a millimetre to a hundred metres (log scale). Clean water stays clear over a few ' +
  'centimetres but its small absorption of red adds up: over tens of metres only blue-green is left. A strong ' +
  'absorber (the illustrative wine-like one) colours light within a centimetre. Scattering does something else: ' +
  'it turns light aside, so the glass ' +
  'first looks cloudy and then, when scattering is strong and absorption weak (milk), opaque and white. The grid ' +
  'sets absorption (upwards) against scattering (across), as in the talk, milk at the lower right. The picture ' +
  'is path traced on the GPU and refines for a moment after each change.';

const MILK_CAVEAT =
  'would pass unscattered if milk scattered evenly in all directions with its reduced ' +
  'coefficient σ′s (the similarity relation, which the picture uses). Milk’s fat globules, about a wavelength ' +
  'across or more, scatter mostly forwards (g > 0 by Lorenz–Mie theory, which Frisvad, Christensen & Jensen 2007 ' +
  'apply to milk; Jensen et al. 2001 give σ′s only), so its true σs = σ′s/(1 − g) is larger and the light that ' +
  'really passes unscattered is less.';

const GRID_READOUT =
  'Across: no, some and strong scattering. Upwards: no, some and strong absorption (strongest in blue). ' +
  'Bottom right: high scattering, no absorption, white like milk.';
const GRID_DESCRIPTION =
  'Nine glasses in front of a chequered wall: absorption grows upwards, scattering to the right; the top-left is ' +
  'clear dark red, the bottom-right white and opaque like milk.';

/** A depth in metres as the readout shows it: three digits in m, cm or mm. */
export function depthWords(d) {
  if (d >= 1) return `${d.toPrecision(3)} m`;
  return d >= 0.01 ? `${(d * 100).toPrecision(3)} cm` : `${(d * 1000).toPrecision(3)} mm`;
}

/** The plot's depth ticks: whole metres, centimetres or millimetres. */
export const depthTick = (v) => (v == null ? '' : v >= 1 ? `${v} m` : v >= 0.01 ? `${v * 100} cm` : `${v * 1000} mm`);

/** The plot's title for a medium. */
export const plotTitle = (m) =>
  m.reduced
    ? `${m.name}: e^(−(σa + σ′s) d), an upper bound on the light left unscattered (Beer–Lambert, ${m.source})`
    : `${m.name}: light left unscattered and unabsorbed after a depth d (Beer–Lambert, ${m.source})`;

/** The readout (HTML: a swatch of the light that passes, then its shares) and the picture in words. */
export function describeMedia(state) {
  if (state.view === 'grid') return { readout: GRID_READOUT, description: GRID_DESCRIPTION };
  const m = MEDIA[state.medium];
  const d = 10 ** state.distance;
  const T = unscattered(m, d);
  const depth = depthWords(d);
  const shares = `R ${(T[0] * 100).toFixed(1)}%, G ${(T[1] * 100).toFixed(1)}%, B ${(T[2] * 100).toFixed(1)}%`;
  const fate = m.reduced ? MILK_CAVEAT : 'passes without being absorbed or scattered.';
  const sentence = (depthShown) => `White light after ${depthShown} of ${m.name.toLowerCase()}: ${shares} ${fate}`;
  const swatch = `<span class="swatch big" style="background:${rgbToHex(T.map(linearToSrgb))}"></span>`;
  return {
    readout: `${swatch} <span>${sentence(`<strong>${depth}</strong>`)}</span>`,
    description: `A glass of ${m.name.toLowerCase()} ${depth} deep in front of a chequered wall; ${sentence(depth)}`,
  };
}

const rgb = (values) => `(${values.map((x) => texNumber(x)).join(',\\ ')})`;

/** Beer–Lambert for the chosen medium and depth, per RGB channel (the transmittance plot's curves). */
export const FORMULA = declareFormula('media', (state) => {
  const medium = MEDIA[state.medium];
  const depth = 10 ** state.distance;
  const law =
    `T(d) = e^{-\\sigma_t d},\\quad \\sigma_t = \\sigma_a + \\sigma_s = ` +
    `\\sym{medium}{(${extinction(medium)
      .map((x) => texSignificant(x))
      .join(',\\ ')})}\\ \\mathrm{m}^{-1}`;
  const at =
    `\\sym{distance}{d = 10^{${texNumber(state.distance, 2)}}\\ \\mathrm{m} =` +
    ` ${texNumber(depth, 4)}\\ \\mathrm{m}}:\\quad ` +
    `T = ${rgb(unscattered(medium, depth))}`;
  return `\\begin{gathered}${law}\\\\ ${at}\\end{gathered}`;
});
