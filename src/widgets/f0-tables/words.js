// f0-tables, in words: the about text, the columns, the source line and the selection described.
import { METALS, NON_METALS, TABLE_SOURCE } from '../../math/index.js';
import { declareFormula, texNumber, texText } from '../../core/framework/formula-registry.js';
import { impliedIor, materialOf, recomputedSrgb } from './model.js';

export const TITLE = 'F0 tables';

export const ABOUT =
  'Metals reflect a lot and in colour: their specular colour is all the colour they have. Non-metals reflect ' +
  'little and without colour (their colour comes from the diffuse term). The recomputed column applies the ' +
  'sRGB curve to the linear values. It agrees with the printed sRGB to within one unit of the last digit except ' +
  'for Plastic / Glass (Low), whose printed pair is inconsistent (marked): 0.03 linear is 0.19 in sRGB, while the ' +
  'printed 0.21 would be 0.036 linear. ' +
  'Use the links to load a material into the curves or onto the 3-D shape.';

/** Channels as printed: '1.00, 0.71, 0.29'. */
export const channels = (xs) => xs.map((x) => x.toFixed(2)).join(', ');

/** A table's column heads: the recomputed sRGB only when shown. */
export const columns = ({ recomputed }, metal) => [
  'Material',
  'F(0°) linear',
  'F(0°) sRGB (talk)',
  ...(recomputed ? ['sRGB from linear'] : []),
  metal ? 'Measured n, k from' : 'IOR implied',
  'Colour',
  'Load into',
];

/** Under the tables: where they come from, and each printed value that disagrees with itself. */
export function sourceText() {
  const notes = [...METALS, ...NON_METALS]
    .filter((m) => m.note)
    .map((m) => ` ${m.name}: ${m.note}`)
    .join('');
  return `Tables: ${TABLE_SOURCE}. Swatches show the printed sRGB value.${notes}`;
}

/** The selected material in words. */
export function describeSelected(key) {
  const { material: m, metal } = materialOf(key);
  const ior = metal ? '' : `, so an index of refraction near ${impliedIor(m).toFixed(3)}`;
  return (
    `Selected: ${m.name}, a ${metal ? 'metal' : 'non-metal'}; F(0°) linear ${channels(m.linear)}, ` +
    `sRGB ${channels(m.srgb)}${ior}.`
  );
}

const triple = (values, digits) => `(${values.map((x) => texNumber(x, digits)).join(',\\ ')})`;

/** The selected row: its linear F0 through the sRGB curve (IEC 61966-2-1) and, for a non-metal, its n. */
export const FORMULA = declareFormula('f0-tables', (state) => {
  const { material, metal } = materialOf(state.selected);
  const row =
    `\\sym{selected}{${texText(material.name)}}:\\ F_0 = ${triple(material.linear, 3)}` +
    `\\ \\mapsto\\ \\sym{recomputed}{${triple(recomputedSrgb(material), 2)}}\\ \\text{in sRGB}`;
  const srgb = 'C_{\\text{sRGB}} = 1.055\\,C^{1/2.4} - 0.055\\quad (C > 0.0031308)';
  if (metal) return `\\begin{gathered}${row}\\\\ ${srgb}\\end{gathered}`;
  const f0 = texNumber(material.linear[0]);
  const ior =
    `n = \\frac{1 + \\sqrt{F_0}}{1 - \\sqrt{F_0}} = \\frac{1 + \\sqrt{${f0}}}{1 - \\sqrt{${f0}}} = ` +
    texNumber(impliedIor(material), 2);
  return `\\begin{gathered}${row}\\\\ ${srgb}\\\\ ${ior}\\end{gathered}`;
});
