// The measured-BRDF widget's model, as pure functions (testable in Node): the examples it ships, the curves
// and images it draws from a measured table and from fits, and the state it hands to the other widgets.
import { FIT_MODELS, modelBRDF, termParams } from '../../measured/fit.js';
import { MERL_DIMS, MERL_SAMPLES, merlIndex, merlNodeAngles } from '../../measured/merl.js';
import { NDF_TERMS, VISIBILITY_TERMS } from '../../math/brdf.js';
import { matchNdfWidths, ndfHalfWidthDeg } from '../../math/ndf-width.js';
import { directionsFromHalfDiff } from '../../math/half-diff.js';
import { DEG } from '../../math/angles.js';

/** Synthetic files the app makes itself with writeMerl (the MERL database is not ours to ship). */
export const EXAMPLES = {
  ggx: {
    label: 'Synthetic plastic: made by writeMerl from GGX (α 0.2, f0 0.04, c_diff 0.3), not a measurement',
    model: 'ggx',
    params: { alpha: 0.2, f0: [0.04, 0.04, 0.04], cdiff: [0.3, 0.3, 0.3] },
  },
  abc: {
    label: 'Synthetic copper-like metal: made by writeMerl from ABC (a1 40, a2 2.5, f0 0.9/0.6/0.3), not a measurement',
    model: 'abc',
    params: { a1: 40, a2: 2.5, f0: [0.9, 0.6, 0.3], cdiff: [0.05, 0.1, 0.2] },
  },
};

export const VIEW_ANGLES = Float64Array.from({ length: 357 }, (_, i) => -89 + i * 0.5);
const lightDir = (deg) => [-Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
const viewDir = (deg) => [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];

/** f(l, v) per channel over the view angles of the plane of incidence (light at -lightDeg): [r[], g[], b[]]. */
export function planeOfIncidence(f, lightDeg) {
  const l = lightDir(lightDeg);
  const values = Array.from(VIEW_ANGLES, (deg) => f(l, viewDir(deg)));
  return [0, 1, 2].map((c) => values.map((rgb) => rgb[c]));
}

/**
 * The 3-D lobe's inputs for a light lightDeg from n in the plane of incidence: the green channel of the table
 * (and of a fit) as functions of the view direction, their largest value over the lobe view's directions, and
 * the arrows. Green, as the (θh, θd) image shows it: one channel keeps the shape readable.
 */
export function lobe3dSpec(lookup, fitF, lightDeg, directions) {
  const l = lightDir(lightDeg);
  // each lobe evaluated once per direction (the view reads them back by direction, after the maximum)
  const green = (f) => {
    if (!f) return null;
    const values = new Map(directions.map((v) => [v, Math.max(f(l, v)[1], 0)]));
    return (v) => values.get(v);
  };
  const [fA, fB] = [green(lookup), green(fitF)];
  const max = Math.max(1e-9, ...directions.map((v) => Math.max(fA(v), fB ? fB(v) : 0)));
  return { fA, fB, max, directions: { n: [0, 0, 1], l, v: null, h: null, mirror: [-l[0], 0, l[2]] } };
}

/** The fitted BRDF of a fit result as f(l, v) → [r, g, b]. */
export const fitBRDF = (fit) => modelBRDF(fit.model, fit.params);

/** theta_h of every table node in degrees (the x axis of the NDF slice). */
export const THETA_H_DEG = Float64Array.from({ length: MERL_DIMS[0] }, (_, i) => merlNodeAngles(i, 0, 0).thetaH / DEG);

/**
 * The NDF the measurement implies. On the θd = 0 slice l = v = h, so f = c_diff/π + F(0°) D(θh) V(θh, θh) / 4:
 * the slice, summed over RGB, less the diffuse of a fit (`fit`, the best one; none: nothing taken off) and
 * divided by that fit's V at l = v, over its peak, is D(θh)/D(0) as the data has it. Missing nodes are null.
 */
export function measuredNdfSlice(table, fit = null) {
  const cdiff = fit?.params.cdiff ?? [0, 0, 0];
  const floor = (cdiff[0] + cdiff[1] + cdiff[2]) / Math.PI;
  const V = fit ? VISIBILITY_TERMS[FIT_MODELS[fit.model].V] : null;
  const p = fit ? termParams(fit.model, fit.params) : null;
  const values = Array.from(THETA_H_DEG, (deg, i) => {
    const rgb = [0, 1, 2].map((c) => table[c * MERL_SAMPLES + merlIndex(i, 0, 0)]);
    if (rgb.some((x) => x < 0)) return null;
    const c = Math.cos(deg * DEG);
    const vis = V ? V({ nl: c, nv: c, nh: c, lh: 1 }, p) : 1;
    return vis > 0 ? (rgb[0] + rgb[1] + rgb[2] - floor) / vis : null;
  });
  const peak = Math.max(...values.filter((x) => x !== null));
  return values.map((x) => (x === null || !(peak > 0) ? null : x / peak));
}

/** A fit's D(θh) / D(0) at the node angles. */
export function fittedNdfSlice(fit) {
  const { D } = FIT_MODELS[fit.model];
  const p = termParams(fit.model, fit.params);
  const peak = NDF_TERMS[D](1, p);
  return Array.from(THETA_H_DEG, (deg) => NDF_TERMS[D](Math.cos(deg * DEG), p) / peak);
}

/** Half width at half maximum (degrees) of a fit's NDF. */
export function fitHalfWidthDeg(fit) {
  const { D } = FIT_MODELS[fit.model];
  const p = termParams(fit.model, fit.params);
  return ndfHalfWidthDeg((c) => NDF_TERMS[D](c, p));
}

/** |f_fit^(1/3) - f_measured^(1/3)| of the green channel over (θh, θd) at φd: the fit metric's residual. */
export const RESIDUAL_TOP = 0.3; // (1/sr)^(1/3): one colour scale for every model's residual

export function residualImage(measured, fit, phiDeg) {
  const f = fitBRDF(fit);
  return (th, td) => {
    // green channel
    const { l, v } = directionsFromHalfDiff(th, td, phiDeg * DEG);
    if (!(l[2] > 0 && v[2] > 0)) return 0;
    return Math.abs(Math.cbrt(f(l, v)[1]) - Math.cbrt(measured.valueAt(th, td, phiDeg * DEG)[1]));
  };
}

/** A short text of a fit's shape parameters. */
export function describeShape(fit) {
  const p = fit.params;
  const g = (x) => x.toPrecision(4);
  return FIT_MODELS[fit.model].shape.map((s) => `${s.key === 'alpha' ? 'α' : s.key} ${g(p[s.key])}`).join(', ');
}

const clamp = (x, lo, hi) => Math.min(Math.max(x, lo), hi);
const mean = (x) => (x[0] + x[1] + x[2]) / 3;

/**
 * brdf-lobe's state for a fit: its D and V, the GGX α of the same half width (brdf-lobe gives ABC and SGD
 * their default shapes at that width), F0 the mean of the fitted RGB f0. brdf-lobe has no diffuse term.
 */
export function lobeStateForFit(fit) {
  const alpha = matchNdfWidths(clamp(fitHalfWidthDeg(fit), 0.5, 60)).ggx.alpha;
  return {
    D: FIT_MODELS[fit.model].D,
    V: FIT_MODELS[fit.model].V,
    F: 'schlick',
    alpha: clamp(alpha, 0.02, 1),
    f0: clamp(mean(fit.params.f0), 0, 1),
  };
}

/** The best fit (smallest error) of those there, or null. */
export const bestFit = (fits) => Object.values(fits).sort((a, b) => a.error - b.error)[0] ?? null;

/**
 * ndf-explorer's state for a fit: its half width, the fitted ABC a2 and SGD p when those fits are there, and
 * the measured slice (measuredNdfSlice with the best fit, 3 digits, 0 where missing or under 1e-5) with `name`
 * (characters a state text field does not take are dropped).
 */
export function ndfStateForFit(fit, fits, measured, name) {
  const state = { hwhm: clamp(fitHalfWidthDeg(fit), 1, 40) };
  if (fits.abc) state.abcA2 = clamp(fits.abc.params.a2, 0.5, 10);
  if (fits.sgd) state.sgdP = clamp(fits.sgd.params.p, 0, 1.9);
  const slice = measuredNdfSlice(measured.table, bestFit(fits));
  state.measured = slice.map((x) => (x > 1e-5 ? Math.min(+x.toPrecision(3), 1) : 0));
  state.measuredName = name.replace(/[^\p{L}\p{N} ._()+,-]/gu, '').slice(0, 80);
  return state;
}
