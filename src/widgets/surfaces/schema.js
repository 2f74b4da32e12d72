// surfaces, its settings as plain data (loads in Node without three.js or the DOM).
import { METALS, NON_METALS } from '../../math/materials.js';

export const TERMS_USED = ['fresnelDielectric', 'fresnelConductor', 'smithG1Beckmann'];

export const schema = {
  material: {
    type: 'enum',
    options: Object.fromEntries([...NON_METALS, ...METALS].map((m) => [m.key, m.name])),
    default: 'glass-high',
    label: 'Material',
  },
  theta: { type: 'number', min: 0, max: 89, step: 1, default: 40, label: 'Angle of incidence', unit: '°' },
  alpha: { type: 'number', min: 0.02, max: 0.8, step: 0.01, default: 0.2, label: 'Microsurface roughness α' },
};
