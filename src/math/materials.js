// The talk's two tables of normal-incidence Fresnel reflectance F(0°), linear and sRGB, as printed
// (Hoffman 2013, after Real-Time Rendering 3rd ed., A K Peters 2008), and each material's exact-Fresnel
// description derived from them.
import { conductorIorFromF0EdgeTint, edgeTintFromConductorIor, f0FromIor, iorFromF0 } from './fresnel.js';
import { MEASURED_NK, measuredRgbNk } from './optical-constants.js';

export const TABLE_SOURCE = 'Hoffman, "Background: Physics and Math of Shading", SIGGRAPH 2013 (table from RTR3)';

export const METALS = [
  { key: 'gold', name: 'Gold', linear: [1.0, 0.71, 0.29], srgb: [1.0, 0.86, 0.57] },
  { key: 'silver', name: 'Silver', linear: [0.95, 0.93, 0.88], srgb: [0.98, 0.97, 0.95] },
  { key: 'copper', name: 'Copper', linear: [0.95, 0.64, 0.54], srgb: [0.98, 0.82, 0.76] },
  { key: 'iron', name: 'Iron', linear: [0.56, 0.57, 0.58], srgb: [0.77, 0.78, 0.78] },
  { key: 'aluminum', name: 'Aluminum', linear: [0.91, 0.92, 0.92], srgb: [0.96, 0.96, 0.97] },
];

export const NON_METALS = [
  { key: 'water', name: 'Water', linear: [0.02, 0.02, 0.02], srgb: [0.15, 0.15, 0.15] },
  // printed as in the talk, though the pair disagrees: 0.03 linear is 0.19 sRGB, and 0.21 sRGB is 0.036 linear
  {
    key: 'glass-low',
    name: 'Plastic / Glass (Low)',
    linear: [0.03, 0.03, 0.03],
    srgb: [0.21, 0.21, 0.21],
    note: 'the printed pair disagrees: 0.03 linear is 0.19 in sRGB, and the printed 0.21 sRGB is 0.036 linear.',
  },
  { key: 'plastic-high', name: 'Plastic High', linear: [0.05, 0.05, 0.05], srgb: [0.24, 0.24, 0.24] },
  { key: 'glass-high', name: 'Glass (High) / Ruby', linear: [0.08, 0.08, 0.08], srgb: [0.31, 0.31, 0.31] },
  { key: 'diamond', name: 'Diamond', linear: [0.17, 0.17, 0.17], srgb: [0.45, 0.45, 0.45] },
];

/** How a metal's exact curve gets its (n, k): from the talk's F0 plus a measured edge tint, or measured alone. */
export const CONDUCTOR_MODELS = { 'f0-tint': 'Talk F0 + measured edge tint', measured: 'Measured n, k' };

export function materialByKey(key) {
  return METALS.find((m) => m.key === key) ?? NON_METALS.find((m) => m.key === key);
}

export const isMetal = (key) => METALS.some((m) => m.key === key);

/**
 * Exact-Fresnel parameters of a table material, per RGB channel: [[eta, k], x3].
 * Non-metals: eta from the talk's F0 (k = 0). Metals, 'measured': the published (n, k) at 650/550/450 nm.
 * Metals, 'f0-tint': Gulbrandsen's (n, k) from the talk's F0 and the edge tint of the measured data,
 * which reproduces the table's F0 exactly while keeping the measured shape towards grazing.
 */
export function channelIor(key, conductorModel = 'f0-tint') {
  const m = materialByKey(key);
  if (!isMetal(key)) return m.linear.map((f0) => [iorFromF0(f0), 0]);
  const measured = measuredRgbNk(key);
  if (conductorModel === 'measured') return measured;
  return m.linear.map((f0, i) => conductorIorFromF0EdgeTint(f0, edgeTintFromConductorIor(...measured[i])));
}

export const measuredSource = (key) => MEASURED_NK[key]?.source;

/** Everything a Fresnel evaluation of a table material needs, per channel: { metal, eta, k, f0 }. */
export function fresnelParams(key, conductorModel = 'f0-tint') {
  const iors = channelIor(key, conductorModel);
  return {
    metal: isMetal(key),
    eta: iors.map(([n]) => n),
    k: iors.map(([, k]) => k),
    f0: iors.map(([n, k]) => f0FromIor(n, k)),
  };
}
