// The diffuse explorer's model, pure functions (no DOM) of the catalogue's diffuse terms: each model's f of the
// cosines and the azimuth, the brightness profile across a sphere, the radiance as the light sweeps past a fixed
// view, and the light a surface returns (specular plus diffuse) against the view angle.
import { termEntry } from '../../math/catalogue/index.js';
import { fresnelSchlick } from '../../math/fresnel.js';
import { punctualRadiance } from '../../math/brdf.js';
import { DEG } from '../../math/angles.js';
import { SERIES_COLORS } from '../../core/ui/palettes.js';
import { schema } from './schema.js';

export const CUSTOM = 'custom';

/**
 * f(nl, nv, cosPhi, { cdiff, f0, sigma, custom }) of the diffuse model `key`, in 1/sr, as the catalogue evaluates
 * it; the user's (`custom`) by params.custom(nl, nv, cosPhi), its values read back from the GPU (custom.js).
 */
export const diffuseAt = (key, nl, nv, cosPhi, params) =>
  key === CUSTOM ? params.custom(nl, nv, cosPhi) : termEntry('diffuse', key).evaluate(nl, nv, cosPhi, params);

/** The models whose f reads no azimuth: their albedo is an integral over n·l alone (any other takes both). */
const AZIMUTH_FREE = new Set(['lambert', 'fresnelWeighted', 'ashikhminShirley']);

/** A model's colour in every plot and table, by its place in the menu. */
export const modelColor = (key) =>
  SERIES_COLORS[Object.keys(schema.diffuse.options).indexOf(key) % SERIES_COLORS.length];

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * cos of the azimuth between l and v about the normal n: the angle between their projections on the tangent
 * plane. 1 where either lies along n (no model depends on it there), as in shaders/diffuse.glsl.
 */
export function cosPhiDiff(n, l, v) {
  const lt = l.map((x, i) => x - dot(n, l) * n[i]);
  const vt = v.map((x, i) => x - dot(n, v) * n[i]);
  const d = dot(lt, lt) * dot(vt, vt);
  return d > 1e-12 ? Math.min(Math.max(dot(lt, vt) / Math.sqrt(d), -1), 1) : 1;
}

/** Reflected radiance per unit light, L_o / c_light = pi f (n·l), of `model` at normal n (all unit, one frame). */
export function radianceAt(model, n, l, v, params) {
  const nl = dot(n, l);
  const nv = dot(n, v);
  return punctualRadiance(diffuseAt(model, nl, nv, cosPhiDiff(n, l, v), params), nl, 1);
}

/**
 * The shading parameters of a state: c_diff, specular F0, sigma in radians, and the user's f(nl, nv, cosPhi)
 * (`custom`; 0 while none has run).
 */
export const paramsOf = (state, custom = null) => ({
  cdiff: state.cdiff,
  f0: state.f0,
  sigma: state.sigma * DEG,
  custom: custom ?? (() => 0),
});

export const PROFILE_XS = Float64Array.from({ length: 201 }, (_, i) => -1 + i / 100);

/**
 * Brightness across the sphere's diameter that points towards the light (azimuth lightPhi), seen head-on
 * (v = z): position s in sphere radii, normal (s cos phi, s sin phi, sqrt(1 - s²)). One array per model.
 */
export function profile(state, lightDir, custom) {
  const p = paramsOf(state, custom);
  const phi = state.lightPhi * DEG;
  const normalAt = (s) => [s * Math.cos(phi), s * Math.sin(phi), Math.sqrt(Math.max(1 - s * s, 0))];
  return state.diffuse.map((m) => PROFILE_XS.map((s) => radianceAt(m, normalAt(s), lightDir, [0, 0, 1], p)));
}

export const SWEEP_XS = Float64Array.from({ length: 361 }, (_, i) => -90 + i / 2);

/**
 * Radiance per unit light on a flat patch (n = z) seen from viewTheta, as the light sweeps through the plane
 * of n and v: theta_l > 0 on the viewer's side (theta_l = theta_v sends light back to the eye), < 0 across.
 */
export function lightSweep(state, custom) {
  const p = paramsOf(state, custom);
  const tv = state.viewTheta * DEG;
  const v = [Math.sin(tv), 0, Math.cos(tv)];
  return state.diffuse.map((m) =>
    SWEEP_XS.map((deg) => radianceAt(m, [0, 0, 1], [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)], v, p)),
  );
}

export const TRADE_XS = Float64Array.from({ length: 90 }, (_, i) => i + 0.5);

/**
 * Directional albedo of a diffuse model seen from cos theta_v = nv: ∫ f (n·l) dω_l by the midpoint rule in
 * (mu = n·l, phi). With v in the x-z plane the azimuth difference is phi itself, and f depends on cos phi
 * only, so phi runs over [0, pi] and counts twice; models without an azimuth need mu alone.
 */
export function diffuseAlbedo(model, nv, params, n = 32) {
  const f = (mu, cosPhi) => diffuseAt(model, mu, nv, cosPhi, params);
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const mu = (i + 0.5) / n;
    if (AZIMUTH_FREE.has(model)) sum += f(mu, 1) * mu * n;
    else for (let j = 0; j < n; j++) sum += f(mu, Math.cos((Math.PI * (j + 0.5)) / n)) * mu;
  }
  return (2 * Math.PI * sum) / (n * n);
}

/**
 * The share of incoming light a surface sends back when its diffuse term sits under a smooth specular one of
 * reflectance F(theta_v) (Schlick, F0): F + diffuse albedo, per model, and F alone. Above 1 means energy is made.
 */
export function tradeOff(state, custom) {
  const p = paramsOf(state, custom);
  const specular = TRADE_XS.map((deg) => fresnelSchlick(p.f0, Math.cos(deg * DEG)));
  const totals = state.diffuse.map((m) =>
    TRADE_XS.map((deg, i) => specular[i] + diffuseAlbedo(m, Math.cos(deg * DEG), p)),
  );
  return { specular, totals };
}
