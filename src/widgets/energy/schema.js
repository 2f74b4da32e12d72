// The white furnace's state: the roughness sweep, the energy compensation, and the coloured metal shown with it.
import { METALS } from '../../math/materials.js';
import { termOptions } from '../../math/catalogue/index.js';

export const schema = {
  alphas: {
    type: 'set',
    // '1.0', not '1': an integer-like key would be listed first
    options: { 0.05: 'α 0.05', 0.25: 'α 0.25', 0.5: 'α 0.5', 0.75: 'α 0.75', '1.0': 'α 1' },
    default: ['0.05', '0.25', '0.5', '0.75', '1.0'],
    label: 'Roughness sweep',
  },
  compensation: {
    type: 'enum',
    options: termOptions('compensation'),
    default: 'none',
    label: 'Energy compensation',
  },
  metal: {
    type: 'enum',
    options: Object.fromEntries(METALS.map((m) => [m.key, m.name])),
    default: 'gold',
    label: 'Coloured metal',
  },
  metalAlpha: { type: 'number', min: 0.05, max: 1, step: 0.05, default: 0.8, label: 'Metal roughness α' },
};
