// fresnel-zones, its model as pure functions: which program a state needs, the values its uniforms take, the
// light directions of the average, zone shares from zone totals, and the terms the probe reads out.
import { ZONE_PALETTES, hexToRgb } from '../../core/ui/palettes.js';
import { lightDirFromAngles } from '../../math/angles.js';
import { microfacetBRDFAt, punctualRadiance } from '../../math/brdf.js';
import { termDefines } from '../../math/catalogue/index.js';
import { srgbToLinear } from '../../math/color.js';
import { fresnelConductor, fresnelDielectric, fresnelSchlick } from '../../math/fresnel.js';
import { fresnelParams } from '../../math/materials.js';
import { ndfGGX } from '../../math/ndf.js';
import { visibilitySmithGGXCorrelated } from '../../math/visibility.js';
import { fresnelZone, sphereZoneFractions } from '../../math/zones.js';

export const AVERAGE_LIGHTS = 64; // light directions, uniform over the sphere (Fibonacci lattice)
/** The rest of the BRDF the weighted mode weighs the zones by, as the catalogue names its terms. */
export const WEIGHT_TERMS = { D: 'ggx', V: 'smithGGXCorrelated' };

export const zonesByLh = (state) => state.mode.startsWith('zones-lh');
export const isWeighted = (state) => state.mode === 'zones-lh-weighted';
/** Whether the light changes the picture: only the zones of l·h depend on it (n·v is the viewer's alone). */
export const lightMatters = zonesByLh;

/** Light directions (theta, phi in degrees, view space) spread uniformly over the whole sphere. */
export function sphereLights(n) {
  const golden = Math.PI * (3 - Math.sqrt(5));
  return Array.from({ length: n }, (_, i) => {
    const z = 1 - (2 * (i + 0.5)) / n;
    return [(Math.acos(z) * 180) / Math.PI, ((i * golden * 180) / Math.PI) % 360];
  });
}

/**
 * The switches of shaders/fresnel-zones.frag.glsl for a state: the picture, or (`stats`) the one-hot zone
 * coverage the GPU sums, which needs only the zones.
 */
export function programDefines(state, stats) {
  const d = {};
  if (zonesByLh(state)) d.ZONE_BY_LH = 1;
  if (isWeighted(state)) Object.assign(d, { WEIGHTED: 1 }, termDefines(WEIGHT_TERMS));
  if (stats) d.STATS_PASS = 1;
  else if (state.mode === 'fresnel-nv') {
    d.SHOW_FRESNEL = 1;
    if (state.fresnel === 'schlick') d.FRESNEL_SCHLICK = 1;
    if (fresnelParams(state.material).metal) d.METAL = 1;
  }
  return d;
}

/** The uniforms' values, linear where the shader works in linear (the palette's sRGB colours). */
export function uniformValues(state) {
  const p = fresnelParams(state.material, state.conductor);
  return {
    lightDir: lightDirFromAngles(state.lightTheta, state.lightPhi),
    eta: p.eta,
    k: p.k,
    f0: p.f0,
    alpha: state.alpha,
    exposure: state.exposure,
    zoneColors: ZONE_PALETTES[state.palette].colors.map((hex) => hexToRgb(hex).map(srgbToLinear)),
  };
}

/** Zone totals as shares of their sum (all zero when nothing is covered). */
export function sharesOf(totals) {
  const sum = totals[0] + totals[1] + totals[2];
  return sum > 0 ? totals.map((t) => t / sum) : [0, 0, 0];
}

/** The exact shares of n·v zones where they are known: an orthographic sphere. */
export const analyticShares = (state) =>
  state.shape === 'sphere' && state.camera === 'orthographic' && !zonesByLh(state) ? sphereZoneFractions() : null;

const DISPLAY_ONLY = ['palette', 'exposure', 'fresnel', 'conductor']; // change the picture, not the zone shares
const MOVE_AVERAGE = ['shape', 'camera', 'alpha'];
/** Whether a change of these keys changes the zone shares, and the average over light directions. */
export const changesShares = (changed) => !changed.every((k) => DISPLAY_ONLY.includes(k));
export const changesAverage = (changed) => changed.some((k) => MOVE_AVERAGE.includes(k));

/**
 * The terms at one surface point, given its angles `a` ({ nv, nl, nh, lh }): Fresnel of n·v per channel
 * (exact and Schlick), the zones of n·v and l·h, GGX D, Smith V and the radiance D·V reflects.
 */
export function probeTerms(state, a) {
  const p = fresnelParams(state.material, state.conductor);
  const exact = p.eta.map((eta, i) => (p.metal ? fresnelConductor(a.nv, eta, p.k[i]) : fresnelDielectric(a.nv, eta)));
  const schlick = p.f0.map((f0) => fresnelSchlick(f0, a.nv));
  const brdf = microfacetBRDFAt(a, { F: 'one', ...WEIGHT_TERMS, alpha: state.alpha });
  return {
    metal: p.metal,
    exact,
    schlick,
    zoneNv: fresnelZone(a.nv),
    zoneLh: fresnelZone(a.lh),
    ndf: ndfGGX(a.nh, state.alpha),
    visibility: visibilitySmithGGXCorrelated(a.nl, a.nv, state.alpha),
    radiance: punctualRadiance(brdf, a.nl, 1),
  };
}
