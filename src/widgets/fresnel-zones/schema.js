// fresnel-zones, its settings as plain data (loads in Node without three.js or the DOM): the GUI, the URL and
// postMessage all read them from here.
import { ZONE_PALETTE_FIELD } from '../../core/ui/palettes.js';
import { CONDUCTOR_MODELS, METALS, NON_METALS } from '../../math/materials.js';

export const MODES = {
  'fresnel-nv': 'Fresnel reflectance of n·v',
  'zones-nv': 'Zones of n·v',
  'zones-lh': 'Zones of l·h',
  'zones-lh-weighted': 'Zones of l·h × rest of BRDF',
};

export const SHAPES = { sphere: 'Sphere', torusknot: 'Torus knot', teapot: 'Teapot' };

export const schema = {
  mode: { type: 'enum', options: MODES, default: 'fresnel-nv', label: 'Mode' },
  shape: { type: 'enum', options: SHAPES, default: 'sphere', label: 'Shape' },
  camera: {
    type: 'enum',
    options: { orthographic: 'Orthographic', perspective: 'Perspective' },
    default: 'orthographic',
    label: 'Camera',
  },
  material: {
    type: 'enum',
    options: Object.fromEntries([...NON_METALS, ...METALS].map((m) => [m.key, m.name])),
    default: 'glass-low',
    label: 'Material',
  },
  conductor: { type: 'enum', options: CONDUCTOR_MODELS, default: 'f0-tint', label: 'Metal n, k' },
  fresnel: { type: 'enum', options: { exact: 'Exact', schlick: 'Schlick' }, default: 'exact', label: 'Fresnel' },
  alpha: { type: 'number', min: 0.01, max: 1, step: 0.01, default: 0.3, label: 'GGX α (roughness)' },
  exposure: { type: 'number', min: 0.1, max: 10, step: 0.1, default: 1, label: 'Exposure' },
  lightTheta: { type: 'number', min: 0, max: 180, step: 0.1, default: 60, label: 'Light θ from view', unit: '°' },
  lightPhi: { type: 'number', min: -180, max: 180, step: 0.1, default: 35, label: 'Light φ around view', unit: '°' },
  palette: ZONE_PALETTE_FIELD,
};

/** The math functions the widget computes, each with a GLSL twin on the parity page ("Terms used"). */
export const TERMS_USED = [
  'fresnelZone',
  'fresnelDielectric',
  'fresnelConductor',
  'fresnelSchlick',
  'ndfGGX',
  'visibilitySmithGGXCorrelated',
  'linearToSrgb',
];
