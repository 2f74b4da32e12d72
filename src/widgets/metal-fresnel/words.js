// metal-fresnel, in words: the about text, the table's caption and heads, the live formula and the summary for
// screen readers. Every number is computed from src/math.
import { declareFormula, texNumber, texText } from '../../core/framework/formula-registry.js';
import { F82_MU } from '../../math/fresnel.js';
import { materialByKey, measuredSource } from '../../math/materials.js';
import { METAL_MODELS } from './models.js';
import { CHANNELS, compareMetal, worstRow } from './model.js';

export const TITLE = 'Metals near grazing: F82-tint';

/** θ̄ = acos(1/7) in degrees, where F82-tint's tint is defined. */
export const F82_ANGLE_DEG = (Math.acos(F82_MU) * 180) / Math.PI;

export const ABOUT =
  'Past the 2013 talk. Each curve is fitted to the metal’s measured optical constants (n, k) at 650, 550 and ' +
  '450 nm: Schlick keeps F(0°); F82-tint (Hoffman 2019 and 2023, the metal Fresnel of Adobe’s Standard Material ' +
  'and of OpenPBR Surface) keeps F(0°) and a tint, the share of Schlick’s value at θ = ' +
  `${F82_ANGLE_DEG.toFixed(1)}°; Gulbrandsen 2014 keeps F(0°) and an edge tint g, from which it rebuilds (n, k) ` +
  'and evaluates the full Fresnel equations. The “exact” curve is itself RGB, three wavelengths, not a spectrum.';

/** |error| for people: 4 decimals, or, below 1e-12, the rounding of float64 it is. */
export const errorWords = (x) =>
  Math.abs(x) < 1e-12 ? `${Math.abs(x).toExponential(0)} (rounding)` : Math.abs(x).toFixed(4);

/** The table's caption: what its rows are. */
export const TABLE_CAPTION = 'Worst error against the exact curve, 0–90°';

/** Above the table: the worst of each model over all the rows, computed. */
export function tableSummary(rows) {
  const worst = Object.keys(METAL_MODELS).map((model) => {
    const r = worstRow(rows, model);
    const w = r.worst[model];
    return `${METAL_MODELS[model].label} ${errorWords(w.value)} (${r.name} ${CHANNELS[r.channel]})`;
  });
  return (
    'The table: each approximation’s worst error over 0–90° against the exact conductor Fresnel (measured n, k), ' +
    `every channel of the talk’s five metals. Largest: ${worst.join('; ')}.`
  );
}

export const TABLE_HEADS = [
  'Metal',
  'Channel',
  'F(0°)',
  'F82 tint',
  'Edge tint g',
  ...Object.values(METAL_MODELS).map((m) => `max |${m.label} − exact|`),
];

/** Where the metal's (n, k) come from. */
export const sourceLine = (key) => `Measured n, k of ${materialByKey(key).name}: ${measuredSource(key)}.`;

const rgb = (xs) => `(${xs.map((x) => texNumber(x)).join(',\\ ')})`;

/** F82-tint with the chosen metal's fitted F0 and tint, per channel. */
export const FORMULA = declareFormula('metal-fresnel', (state) => {
  const channels = compareMetal(state.metal, [0]);
  const name = `\\sym{metal}{${texText(materialByKey(state.metal).name)}}`;
  const f0 = rgb(channels.map((c) => c.fit.f0));
  const tint = rgb(channels.map((c) => c.fit.tint));
  return (
    '\\begin{gathered}F_{82}(\\mu) = F_{\\text{Schlick}}(F_0, \\mu) - b\\,\\mu(1-\\mu)^6,\\quad ' +
    'b = \\frac{F_{\\text{Schlick}}(F_0, \\bar\\mu)\\,(1 - t)}{\\bar\\mu(1-\\bar\\mu)^6},\\quad ' +
    '\\bar\\mu = \\tfrac{1}{7}' +
    `\\\\ ${name}:\\ F_0 = ${f0},\\ t = ${tint}\\end{gathered}`
  );
});

/** What a reader would look for in the plots: each model's worst error for the metal. */
export function describeMetal(state, channels) {
  const parts = Object.keys(METAL_MODELS)
    .filter((m) => state.models.includes(m))
    .map((model) => {
      const worst = channels.reduce((a, c) =>
        Math.abs(c.models[model].worst.value) > Math.abs(a.models[model].worst.value) ? c : a,
      );
      const w = worst.models[model].worst;
      return `${METAL_MODELS[model].label} ${errorWords(w.value)} (${CHANNELS[worst.channel]}, ${w.at}°)`;
    });
  const name = materialByKey(state.metal).name;
  return `${name}: exact conductor Fresnel per channel against angle. Largest error: ${parts.join('; ') || 'none'}.`;
}
