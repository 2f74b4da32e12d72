// anisotropic-microsurface, its settings as plain data (loads in Node without three.js or the DOM).
export const schema = {
  alphaX: { type: 'number', min: 0.1, max: 1, step: 0.01, default: 0.6, label: 'Roughness along t, αx' },
  alphaY: { type: 'number', min: 0.1, max: 1, step: 0.01, default: 0.2, label: 'Roughness along b, αy' },
  theta: { type: 'number', min: 30, max: 85, step: 1, default: 75, label: 'Light angle from n, θ', unit: '°' },
  phi: { type: 'number', min: 0, max: 180, step: 1, default: 30, label: 'Light azimuth from t, φ', unit: '°' },
  seed: { type: 'number', min: 1, max: 999, step: 1, default: 3, label: 'Surface seed' },
};

/** The math functions the widget computes, each with a GLSL twin on the parity page ("Terms used"). */
export const TERMS_USED = ['smithG1BeckmannAniso'];

/** The settings that make a new surface (and a new G1 measurement). */
export const SURFACE_KEYS = ['alphaX', 'alphaY', 'seed'];
/** The settings that make a new G1 measurement: those and θ; φ only redraws the picture and the table. */
export const SWEEP_KEYS = [...SURFACE_KEYS, 'theta'];
