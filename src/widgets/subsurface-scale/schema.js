// subsurface-scale, its settings as plain data (loads in Node without three.js or the DOM).

export const TERMS_USED = []; // JS only (src/math/media.js): nothing here runs on the GPU

export const schema = {
  sigmaS: { type: 'number', min: 0.2, max: 20, step: 0.1, default: 2, label: 'Scattering σs', unit: '1/mm' },
  sigmaA: { type: 'number', min: 0, max: 2, step: 0.01, default: 0.05, label: 'Absorption σa', unit: '1/mm' },
  pixel: { type: 'number', min: 0.05, max: 20, step: 0.05, default: 4, label: 'Shading sample radius', unit: 'mm' },
  walks: { type: 'number', min: 5, max: 200, step: 1, default: 40, label: 'Paths drawn' },
  seed: { type: 'number', min: 1, max: 999, step: 1, default: 1, label: 'Seed' },
};
