// media, its settings as plain data (loads in Node without three.js or the DOM): the media to choose from,
// and the state the GUI, the URL and postMessage read.
import { WATER_K, WHOLE_MILK, waterAbsorptionRgb } from '../../math/media.js';

export const TERMS_USED = ['transmittance'];

export const MEDIA = {
  water: { name: 'Clean water', sigmaA: waterAbsorptionRgb(), sigmaS: [0, 0, 0], source: WATER_K.source },
  red: {
    name: 'Red absorber (wine-like, illustrative)',
    sigmaA: [3, 60, 90],
    sigmaS: [0, 0, 0],
    source: 'illustrative values',
  },
  cloudy: {
    name: 'Cloudy water (illustrative)',
    sigmaA: waterAbsorptionRgb(),
    sigmaS: [25, 25, 25],
    source: 'water plus illustrative scattering',
  },
  // milk's σ′s stands in for σs with isotropic scattering (the similarity relation): the picture diffuses light as
  // milk does, but the straight-through light it implies is only an upper bound on milk's
  milk: {
    name: 'Whole milk (reduced scattering σ′s)',
    sigmaA: WHOLE_MILK.sigmaA,
    sigmaS: WHOLE_MILK.sigmaSReduced,
    source: WHOLE_MILK.source,
    reduced: true,
  },
};

export const schema = {
  view: {
    type: 'enum',
    options: { one: 'One glass', grid: 'The talk’s grid of glasses' },
    default: 'one',
    label: 'View',
  },
  medium: {
    type: 'enum',
    options: Object.fromEntries(Object.entries(MEDIA).map(([k, m]) => [k, m.name])),
    default: 'water',
    label: 'Medium',
  },
  distance: { type: 'number', min: -3, max: 2, step: 0.05, default: -1.3, label: 'Depth, log₁₀ metres' },
  samples: {
    type: 'enum',
    options: { 16: '16', 64: '64', 256: '256', 1024: '1024' },
    default: '64',
    label: 'Samples per pixel',
  },
};
