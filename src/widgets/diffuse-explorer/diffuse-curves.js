// The data behind the diffuse explorer's plots, from src/math only (no DOM): each diffuse model as a function
// of the cosines and the azimuth, the brightness profile across a sphere, the radiance as the light sweeps
// past a fixed view, and the light a surface returns (specular plus diffuse) against the view angle.
import {
  diffuseAshikhminShirley,
  diffuseFresnelWeighted,
  diffuseLambert,
  diffuseOrenNayar,
  diffuseOrenNayarQualitative,
} from '../../math/diffuse.js';
import { fresnelSchlick } from '../../math/fresnel.js';
import { punctualRadiance } from '../../math/brdf.js';
import { DEG } from '../../math/angles.js';

/**
 * Every model: its name, the shader switch that picks it, whether it depends on the azimuth between l and v,
 * and f(nl, nv, cosPhi, { cdiff, f0, sigma }) in 1/sr.
 */
export const MODELS = {
  lambert: {
    name: 'Lambert',
    short: 'Lambert',
    define: 'DIFFUSE_LAMBERT',
    f: (nl, nv, cp, p) => (nl > 0 && nv > 0 ? diffuseLambert(p.cdiff) : 0),
  },
  fresnelWeighted: {
    name: 'Fresnel-weighted Lambert',
    short: 'Fresnel-weighted',
    define: 'DIFFUSE_FRESNEL_WEIGHTED',
    f: (nl, nv, cp, p) => diffuseFresnelWeighted(nl, nv, p.f0, p.cdiff),
  },
  ashikhminShirley: {
    name: 'Ashikhmin–Shirley',
    short: 'Ashikhmin–Shirley',
    define: 'DIFFUSE_ASHIKHMIN_SHIRLEY',
    f: (nl, nv, cp, p) => diffuseAshikhminShirley(nl, nv, p.f0, p.cdiff),
  },
  orenNayar: {
    name: 'Oren–Nayar (full)',
    short: 'Oren–Nayar',
    define: 'DIFFUSE_OREN_NAYAR',
    azimuthal: true,
    f: (nl, nv, cp, p) => diffuseOrenNayar(nl, nv, cp, p.sigma, p.cdiff),
  },
  orenNayarQualitative: {
    name: 'Oren–Nayar (qualitative)',
    short: 'O–N qualitative',
    define: 'DIFFUSE_OREN_NAYAR_QUALITATIVE',
    azimuthal: true,
    f: (nl, nv, cp, p) => diffuseOrenNayarQualitative(nl, nv, cp, p.sigma, p.cdiff),
  },
};

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
  return punctualRadiance(MODELS[model].f(nl, nv, cosPhiDiff(n, l, v), params), nl, 1);
}

/** The shading parameters of a state: c_diff, specular F0, sigma in radians. */
export const paramsOf = (state) => ({ cdiff: state.cdiff, f0: state.f0, sigma: state.sigma * DEG });

export const PROFILE_XS = Float64Array.from({ length: 201 }, (_, i) => -1 + i / 100);

/**
 * Brightness across the sphere's diameter that points towards the light (azimuth lightPhi), seen head-on
 * (v = z): position s in sphere radii, normal (s cos phi, s sin phi, sqrt(1 - s²)). One array per model.
 */
export function profile(state, lightDir) {
  const p = paramsOf(state);
  const phi = state.lightPhi * DEG;
  const normalAt = (s) => [s * Math.cos(phi), s * Math.sin(phi), Math.sqrt(Math.max(1 - s * s, 0))];
  return state.models.map((m) => PROFILE_XS.map((s) => radianceAt(m, normalAt(s), lightDir, [0, 0, 1], p)));
}

export const SWEEP_XS = Float64Array.from({ length: 361 }, (_, i) => -90 + i / 2);

/**
 * Radiance per unit light on a flat patch (n = z) seen from viewTheta, as the light sweeps through the plane
 * of n and v: theta_l > 0 on the viewer's side (theta_l = theta_v sends light back to the eye), < 0 across.
 */
export function lightSweep(state) {
  const p = paramsOf(state);
  const tv = state.viewTheta * DEG;
  const v = [Math.sin(tv), 0, Math.cos(tv)];
  return state.models.map((m) =>
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
  const { f, azimuthal } = MODELS[model];
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const mu = (i + 0.5) / n;
    if (!azimuthal) sum += f(mu, nv, 1, params) * mu * n;
    else for (let j = 0; j < n; j++) sum += f(mu, nv, Math.cos((Math.PI * (j + 0.5)) / n), params) * mu;
  }
  return (2 * Math.PI * sum) / (n * n);
}

/**
 * The share of incoming light a surface sends back when its diffuse term sits under a smooth specular one of
 * reflectance F(theta_v) (Schlick, F0): F + diffuse albedo, per model, and F alone. Above 1 means energy is made.
 */
export function tradeOff(state) {
  const p = paramsOf(state);
  const specular = TRADE_XS.map((deg) => fresnelSchlick(p.f0, Math.cos(deg * DEG)));
  const totals = state.models.map((m) =>
    TRADE_XS.map((deg, i) => specular[i] + diffuseAlbedo(m, Math.cos(deg * DEG), p)),
  );
  return { specular, totals };
}
