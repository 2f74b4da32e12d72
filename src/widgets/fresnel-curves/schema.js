// fresnel-curves, its settings as plain data (loads in Node without three.js or the DOM).
import { ZONE_PALETTE_FIELD } from '../../core/ui/palettes.js';
import { CONDUCTOR_MODELS, METALS, NON_METALS } from '../../math/materials.js';

const MATERIAL_OPTIONS = Object.fromEntries([
  ...METALS.map((m) => [m.key, m.name]),
  ...NON_METALS.map((m) => [m.key, m.name]),
  ['manual', 'Custom dielectric (IOR below)'],
]);

export const schema = {
  materials: {
    type: 'set',
    options: MATERIAL_OPTIONS,
    aliases: { custom: 'manual' }, // `custom` names the user's own GLSL elsewhere; old links' `custom` is read
    default: ['copper', 'aluminum', 'glass-low', 'diamond'],
    label: 'Materials',
  },
  ior: { type: 'number', min: 1, max: 3, step: 0.01, default: 1.5, label: 'Custom IOR' },
  conductor: {
    type: 'enum',
    options: CONDUCTOR_MODELS,
    default: 'f0-tint',
    label: 'Metal n, k',
    hint:
      'Talk F0 + edge tint: Gulbrandsen 2014’s fitted n, k (a reparametrisation that reproduces the table, not ' +
      'optical constants). Measured: published optical constants at 650/550/450 nm.',
  },
  schlick: { type: 'bool', default: true, label: 'Show Schlick' },
  zones: { type: 'bool', default: true, label: 'Shade zones' },
  palette: ZONE_PALETTE_FIELD,
};

/** The math functions the widget computes, each with a GLSL twin on the parity page ("Terms used"). */
export const TERMS_USED = ['fresnelDielectric', 'fresnelConductor', 'fresnelSchlick'];
