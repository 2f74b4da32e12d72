// f0-tables, its settings as plain data (loads in Node without three.js or the DOM).
import { METALS, NON_METALS } from '../../math/materials.js';

export const schema = {
  selected: {
    type: 'enum',
    options: Object.fromEntries([...METALS, ...NON_METALS].map((m) => [m.key, m.name])),
    default: 'gold',
    label: 'Selected',
  },
  recomputed: { type: 'bool', default: true, label: 'Show recomputed sRGB' },
};

/** The math functions the widget computes, each with a GLSL twin on the parity page ("Terms used"). */
export const TERMS_USED = ['linearToSrgb', 'srgbToLinear'];
