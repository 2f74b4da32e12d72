// fresnel-curves, its model as pure functions: for each chosen material, exact Fresnel and Schlick's
// approximation against the angle of incidence (one curve per RGB channel for metals), and the zones behind.
import { SERIES_COLORS, ZONE_PALETTES, withAlpha } from '../../core/ui/palettes.js';
import { fresnelConductor, fresnelDielectric, fresnelSchlick, f0FromIor } from '../../math/fresnel.js';
import { channelIor, isMetal, materialByKey } from '../../math/materials.js';
import { FRESNEL_ZONE_BOUNDS_DEG } from '../../math/zones.js';

export const ANGLE_STEP_DEG = 0.25;
export const CHANNELS = ['R', 'G', 'B'];

export function angleGrid(step = ANGLE_STEP_DEG) {
  const n = Math.round(90 / step) + 1;
  return Float64Array.from({ length: n }, (_, i) => i * step);
}

/**
 * [{ key, name, metal, channel (0..2 or null), eta, k, fitted }] for the chosen materials. `fitted`: (eta, k) are
 * Gulbrandsen's parameters fitted to F0 and an edge tint, not measured optical constants.
 */
export function curveSpecs({ materials, conductor, ior }) {
  const specs = [];
  for (const key of materials) {
    if (key === 'manual') {
      specs.push({ key, name: `Dielectric n = ${ior.toFixed(2)}`, metal: false, channel: null, eta: ior, k: 0 });
      continue;
    }
    const m = materialByKey(key);
    const iors = channelIor(key, conductor);
    const fitted = conductor !== 'measured';
    if (isMetal(key)) {
      iors.forEach(([eta, k], channel) => specs.push({ key, name: m.name, metal: true, channel, eta, k, fitted }));
    } else specs.push({ key, name: m.name, metal: false, channel: null, eta: iors[0][0], k: 0 });
  }
  return specs;
}

/** Exact, Schlick (with the exact curve's own F0) and Schlick − exact, sampled at `angles` (degrees). */
export function evaluateCurve(spec, angles) {
  const f0 = f0FromIor(spec.eta, spec.k);
  const exact = new Float64Array(angles.length);
  const schlick = new Float64Array(angles.length);
  const error = new Float64Array(angles.length);
  let maxAbs = 0;
  let maxAt = 0;
  angles.forEach((deg, i) => {
    const c = Math.cos((deg * Math.PI) / 180);
    exact[i] = spec.k > 0 ? fresnelConductor(c, spec.eta, spec.k) : fresnelDielectric(c, spec.eta);
    schlick[i] = fresnelSchlick(f0, c);
    error[i] = schlick[i] - exact[i];
    if (Math.abs(error[i]) > Math.abs(maxAbs)) [maxAbs, maxAt] = [error[i], deg];
  });
  return { f0, exact, schlick, error, maxError: maxAbs, maxErrorAt: maxAt };
}

/** The talk's three zones as bands behind the curves, in the state's palette (none when they are off). */
function zoneBands(state) {
  if (!state.zones) return [];
  const zoneColors = ZONE_PALETTES[state.palette].colors;
  const [z1, z2] = FRESNEL_ZONE_BOUNDS_DEG;
  return [
    { from: 0, to: z1, color: withAlpha(zoneColors[0], 0.16), label: 'barely changes' },
    { from: z1, to: z2, color: withAlpha(zoneColors[1], 0.22), label: 'changes somewhat' },
    { from: z2, to: 90, color: withAlpha(zoneColors[2], 0.16), label: '→ 1' },
  ];
}

/**
 * Everything the plots and the readout show for a state: the angle grid, the curves (each with its spec,
 * label, colour, one per material, and evaluateCurve's values) and the zone bands.
 */
export function buildSeries(state) {
  const angles = angleGrid();
  const specs = curveSpecs(state);
  const materialOrder = [...new Set(specs.map((s) => s.key))];
  const curves = specs.map((spec) => {
    const label = spec.metal ? `${spec.name} ${CHANNELS[spec.channel]}` : spec.name;
    const stroke = SERIES_COLORS[materialOrder.indexOf(spec.key) % SERIES_COLORS.length];
    return { spec, label, stroke, ...evaluateCurve(spec, angles) };
  });
  return { angles, curves, bands: zoneBands(state) };
}

/** The curve where Schlick is furthest off (null when there is none). */
export const worstCurve = (curves) =>
  curves.reduce((a, c) => (!a || Math.abs(c.maxError) > Math.abs(a.maxError) ? c : a), null);
