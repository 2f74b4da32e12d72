// metal-fresnel, its settings as plain data (loads in Node without three.js or the DOM).
import { METALS } from '../../math/materials.js';
import { METAL_MODELS } from './models.js';

export const schema = {
  metal: {
    type: 'enum',
    options: Object.fromEntries(METALS.map((m) => [m.key, m.name])),
    default: 'aluminum',
    label: 'Metal',
  },
  models: {
    type: 'set',
    options: Object.fromEntries(Object.entries(METAL_MODELS).map(([key, m]) => [key, m.label])),
    default: Object.keys(METAL_MODELS),
    label: 'Approximations',
  },
};

/** The math functions the widget computes, each with a GLSL twin on the parity page ("Terms used"). */
export const TERMS_USED = ['fresnelConductor', 'fresnelSchlick', 'fresnelF82Tint', 'f82TintFromConductor'];
