// f0-tables, its model as pure functions: the talk's two tables, what each row derives (the sRGB recomputed
// from the linear column, the index of refraction a non-metal's F0 implies), and the widgets a row loads into.
import { linearToSrgb } from '../../math/color.js';
import { METALS, NON_METALS, iorFromF0 } from '../../math/index.js';

export const TABLES = [
  { caption: 'Normal-incidence Fresnel for metals', rows: METALS, metal: true },
  { caption: 'Normal-incidence Fresnel for non-metals', rows: NON_METALS, metal: false },
];

/** The talk's linear F(0°) through the sRGB curve, to set against its printed sRGB. */
export const recomputedSrgb = (material) => material.linear.map(linearToSrgb);

/** The index of refraction a non-metal with this F(0°) has (from its first channel: they are grey). */
export const impliedIor = (material) => iorFromF0(material.linear[0]);

/** The material under `key` and whether it is a metal. */
export function materialOf(key) {
  const material = [...METALS, ...NON_METALS].find((m) => m.key === key);
  return { material, metal: METALS.includes(material) };
}

/** The widgets a row loads its material into: [widget, link text, its URL parameters, where it goes, said]. */
export const loadTargets = (key) => [
  ['fresnel-curves', 'curves', `materials=${key}`, 'into the Fresnel curves plot'],
  ['fresnel-zones', '3-D', `material=${key}&mode=fresnel-nv`, 'onto the Fresnel zones 3-D shape'],
];
