// microfacets, its settings as plain data (loads in Node without three.js or the DOM).
export const schema = {
  kind: {
    type: 'enum',
    options: { beckmann: 'Beckmann (Gaussian slopes)', ggx: 'GGX' },
    default: 'beckmann',
    label: 'Slope distribution',
  },
  alpha: { type: 'number', min: 0.1, max: 1, step: 0.01, default: 0.5, label: 'Roughness α' },
  lightTheta: { type: 'number', min: -85, max: 85, step: 1, default: 70, label: 'Light angle θl', unit: '°' },
  viewTheta: { type: 'number', min: -85, max: 85, step: 1, default: -40, label: 'View angle θv', unit: '°' },
  rays: { type: 'number', min: 4, max: 64, step: 1, default: 28, label: 'Rays drawn' },
  bounces: { type: 'bool', default: true, label: 'Follow second bounces' },
  seed: { type: 'number', min: 1, max: 999, step: 1, default: 3, label: 'Surface seed' },
};

/** The math functions the widget computes, each with a GLSL twin on the parity page ("Terms used"). */
export const TERMS_USED = ['smithG1Beckmann', 'smithG1GGX'];

/** The settings that make a new surface (and a new G1 measurement); the others only redraw it. */
export const SURFACE_KEYS = ['kind', 'alpha', 'seed'];
