// radiance, its settings as plain data (loads in Node without three.js or the DOM).
import { LIGHTS, SURFACES } from './model.js';

const names = (table) => Object.fromEntries(Object.entries(table).map(([k, v]) => [k, v.name]));

export const schema = {
  distance: { type: 'number', min: 0.1, max: 30, step: 0.1, default: 1, label: 'Distance to the lamp', unit: 'm' },
  lampRadius: { type: 'number', min: 0.01, max: 0.1, step: 0.01, default: 0.05, label: 'Lamp radius', unit: 'm' },
  light: { type: 'enum', options: names(LIGHTS), default: 'incandescent', label: 'Light spectrum' },
  surface: { type: 'enum', options: names(SURFACES), default: 'red', label: 'Surface reflectance' },
};

export const TERMS_USED = []; // JS only (src/math/radiometry.js): nothing here runs on the GPU
