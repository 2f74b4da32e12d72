// Fitting the talk's microfacet models to a measured BRDF (no DOM: Node and a Web Worker).
//
// Model: f_c = cdiff_c / pi + F_Schlick(f0_c, l·h) D(n·h) V(l, v) / 4 for each channel c. Visibility: the
// height-correlated Smith of GGX for GGX; for Beckmann (and Blinn-Phong, at Walter 2007's matched alpha) the
// separable Smith with the exact G1, the catalogue's Beckmann Smith; ABC and SGD have no Smith form in the
// catalogue, so they take the Cook-Torrance V-cavity term, which needs no roughness.
//
// Error: the cosine-weighted cube-root metric of Ngan, Durand, Matusik 2005 (Experimental analysis of BRDF
// models), E = sqrt( Σ w [ (f_model cos θ)^(1/3) - (f_measured cos θ)^(1/3) ]² / Σ w ), over the table's nodes
// with θl and θv below 80° (Ngan's cut: the grazing data is unreliable), w the solid angle of each node's cell
// in (l, v) space, the RGB channels averaged, θ the incident angle. Each node stands for both of its
// orientations (φd and φd + 180°, l and v swapped), so both cosines enter. Unit: (1/sr)^(1/3).
//
// Optimiser: Nelder-Mead (1965) over the NDF's shape parameters, started from the best point of a coarse grid;
// for each shape the RGB weights (cdiff_c ≥ 0, 0 ≤ f0_c ≤ 1), on which f is linear, are solved per channel by
// box-constrained Gauss-Newton on the same metric, started from a relative least-squares fit.
import { NDF_TERMS, VISIBILITY_TERMS, brdfAngles, microfacetTermsAt } from '../math/brdf.js';
import { fresnelSchlick } from '../math/fresnel.js';
import { beckmannAlphaFromBlinnPhongExponent } from '../math/ndf.js';
import { directionsFromHalfDiff } from '../math/half-diff.js';
import { MERL_DIMS, MERL_SAMPLES, merlIndex, merlNodeAngles, parseMerl, writeMerl } from './merl.js';
import { nelderMead } from './nelder-mead.js';
import { solveWeights } from './weights.js';
import { DEG } from '../math/angles.js';

const RELATIVE_FLOOR = 1e-3; // 1/sr: keeps the first, relative fit's weights finite where m is 0

/** Each model: its NDF and V terms, and its shape parameters with their search ranges. */
const range = (key, min, max, log = true) => ({ key, min, max, log });
export const FIT_MODELS = {
  ggx: { label: 'GGX', D: 'ggx', V: 'smithGGXCorrelated', shape: [range('alpha', 1e-3, 1)] },
  beckmann: { label: 'Beckmann', D: 'beckmann', V: 'smithBeckmannSeparable', shape: [range('alpha', 1e-3, 1)] },
  blinnPhong: {
    label: 'Blinn-Phong',
    D: 'blinnPhong',
    V: 'smithBeckmannSeparable',
    shape: [range('exponent', 1, 1e6)],
  },
  abc: { label: 'ABC', D: 'abc', V: 'cookTorrance', shape: [range('a1', 0.01, 1e4), range('a2', 0.05, 20)] },
  sgd: {
    label: 'Shifted gamma',
    D: 'sgd',
    V: 'cookTorrance',
    shape: [range('alpha', 0.01, 2), range('p', 0, 1.9, false)],
  },
};

/** The NDF/V parameter object NDF_TERMS and VISIBILITY_TERMS read, from a model's shape parameters. */
export function termParams(model, shape) {
  return model === 'blinnPhong'
    ? { ...shape, alpha: beckmannAlphaFromBlinnPhongExponent(shape.exponent) }
    : { ...shape };
}

/** The fitted BRDF as a function f(l, v) → [r, g, b] in 1/sr (also what writeMerl tabulates for tests). */
export function modelBRDF(model, params) {
  const m = FIT_MODELS[model];
  const p = { F: 'one', D: m.D, V: m.V, ...termParams(model, params) };
  return (l, v) => {
    const a = brdfAngles(l, v);
    if (!(a.nl > 0 && a.nv > 0)) return [0, 0, 0];
    const t = microfacetTermsAt(a, p);
    return [0, 1, 2].map((c) => params.cdiff[c] / Math.PI + (fresnelSchlick(params.f0[c], a.lh) * t.D * t.V) / 4);
  };
}

/**
 * The nodes the error is summed over, with their cell weights: every theta_h node, every strideD-th theta_d
 * and strideP-th phi_d node (a cell then spans the skipped ones), θl, θv < maxThetaDeg, no channel missing.
 * Returned as typed arrays: { count, i (theta_h node), nl, nv, nh, lh, s5, w, m: [r, g, b], cbrtM, totalWeight }.
 */
export function fitSamples(measured, { strideD = 3, strideP = 9, maxThetaDeg = 80 } = {}) {
  const [NH, ND, NP] = MERL_DIMS;
  const cosMax = Math.cos(maxThetaDeg * DEG);
  const rows = [];
  for (let i = 0; i < NH; i++) {
    const hCell = Math.cos(merlNodeAngles(i, 0, 0).thetaH) - Math.cos(merlNodeAngles(i + 1, 0, 0).thetaH);
    for (let j = 0; j < ND; j += strideD) {
      const [d0, d1] = [merlNodeAngles(0, j, 0).thetaD, merlNodeAngles(0, Math.min(j + strideD, ND), 0).thetaD];
      const dCell = (Math.sin(d1) ** 2 - Math.sin(d0) ** 2) / 2; // ∫ sin cos dθd: dω_i dω_o = 4 cos θd dω_h dω_d
      for (let k = 0; k < NP; k += strideP) {
        const n = merlIndex(i, j, k);
        const m = [0, 1, 2].map((c) => measured.table[c * MERL_SAMPLES + n]);
        if (m.some((x) => x < 0)) continue;
        const a = merlNodeAngles(i, j, k);
        const { l, v } = directionsFromHalfDiff(a.thetaH, a.thetaD, a.phiD);
        if (!(l[2] > cosMax && v[2] > cosMax)) continue;
        const cosWeight = Math.cbrt(l[2]) ** 2 + Math.cbrt(v[2]) ** 2; // both orientations, l ↔ v
        const w = hCell * dCell * Math.min(strideP, NP - k) * cosWeight;
        rows.push([i, l[2], v[2], Math.cos(a.thetaH), Math.cos(a.thetaD), w, ...m]);
      }
    }
  }
  const column = (k) => Float64Array.from(rows, (r) => r[k]);
  const lh = column(4);
  const m = [6, 7, 8].map(column);
  const w = column(5);
  return {
    count: rows.length,
    i: Uint8Array.from(rows, (r) => r[0]),
    nl: column(1),
    nv: column(2),
    nh: column(3),
    lh,
    s5: lh.map((c) => fresnelSchlick(0, c)),
    w,
    cbrtM: m.map((x) => x.map(Math.cbrt)),
    totalWeight: w.reduce((s, x) => s + x, 0),
    relativeW: m.map((x) => x.map((mi, s) => w[s] / (mi + RELATIVE_FLOOR) ** (4 / 3))),
  };
}

/** The specular factor D V / 4 at each sample for shape parameters `p` (D taken once per theta_h node). */
function specularFactors(samples, model, p) {
  const { D, V } = FIT_MODELS[model];
  const dAt = Float64Array.from({ length: MERL_DIMS[0] }, (_, i) => {
    const t = merlNodeAngles(i, 0, 0).thetaH;
    return NDF_TERMS[D](Math.cos(t), p, Math.sin(t) ** 2);
  });
  const vis = VISIBILITY_TERMS[V];
  const a = { nl: 0, nv: 0, nh: 0, lh: 0 };
  const S = new Float64Array(samples.count);
  for (let s = 0; s < samples.count; s++) {
    [a.nl, a.nv, a.nh, a.lh] = [samples.nl[s], samples.nv[s], samples.nh[s], samples.lh[s]];
    S[s] = (dAt[samples.i[s]] * vis(a, p)) / 4;
  }
  return S;
}

/** Error and RGB weights of one shape: { error, f0, cdiff }. */
export function evaluateShape(samples, model, shape) {
  const S = specularFactors(samples, model, termParams(model, shape));
  const f0 = [];
  const cdiff = [];
  let sum = 0;
  for (let c = 0; c < 3; c++) {
    const fit = solveWeights(samples, S, c);
    f0.push(fit.f0);
    cdiff.push(fit.cdiff);
    sum += fit.sumSq;
  }
  return { error: Math.sqrt(sum / (3 * samples.totalWeight)), f0, cdiff };
}

const toShape = (model, z) =>
  Object.fromEntries(
    FIT_MODELS[model].shape.map((s, i) => {
      const x = s.log ? Math.exp(z[i]) : z[i];
      return [s.key, Math.min(Math.max(x, s.min), s.max)];
    }),
  );

/** A coarse grid over the shape ranges (z space), from which the simplex starts. */
function startGrid(model) {
  const axes = FIT_MODELS[model].shape.map((s) => {
    const [lo, hi] = s.log ? [Math.log(s.min), Math.log(s.max)] : [s.min, s.max];
    const n = FIT_MODELS[model].shape.length === 1 ? 12 : 5;
    return Array.from({ length: n }, (_, i) => lo + ((i + 0.5) / n) * (hi - lo));
  });
  return axes.reduce((acc, axis) => acc.flatMap((p) => axis.map((x) => [...p, x])), [[]]);
}

/**
 * Fits `model` (a key of FIT_MODELS) to a measured BRDF ({ table } as parseMerl returns).
 * options: { samples (from fitSamples, to share between models), strideD, strideP, maxThetaDeg,
 * maxEvaluations (default 400), onProgress({ model, evaluations, error }) }.
 * Returns { model, params: { ...shape, f0: [r, g, b], cdiff: [r, g, b] }, error, evaluations }.
 */
export function fitMeasured(measured, model, options = {}) {
  if (!FIT_MODELS[model]) throw new Error(`Unknown model "${model}": one of ${Object.keys(FIT_MODELS).join(', ')}.`);
  const samples = options.samples ?? fitSamples(measured, options);
  let evaluations = 0;
  const cost = (z) => {
    evaluations++;
    const e = evaluateShape(samples, model, toShape(model, z)).error;
    if (evaluations % 10 === 0) options.onProgress?.({ model, evaluations, error: e });
    return e;
  };
  const grid = startGrid(model).map((z) => ({ z, e: cost(z) }));
  const start = grid.reduce((a, b) => (b.e < a.e ? b : a));
  const best = nelderMead(cost, start.z, {
    step: 0.5,
    maxEvaluations: options.maxEvaluations ?? 400,
    xTolerance: 1e-5,
  });
  const shape = toShape(model, best.x);
  const fit = evaluateShape(samples, model, shape);
  return { model, params: { ...shape, f0: fit.f0, cdiff: fit.cdiff }, error: fit.error, evaluations };
}

/** A table written by writeMerl from `model` with `params` and read back as a file would be: { table, missing, … }. */
export const synthesizeTable = (model, params) => parseMerl(writeMerl(modelBRDF(model, params)));

/**
 * Fits each of `models` to `measured` on the same samples (fitSamples with `options`), in order:
 * onProgress(progress, index) as fitMeasured reports it, onFitted(result, index, ms) after each.
 * Returns { model: result }. The fit worker and scripts/example-fits.js both fit this way.
 */
export function fitModels(measured, models, options = {}, { onProgress, onFitted } = {}) {
  const samples = fitSamples(measured, options);
  return Object.fromEntries(
    models.map((model, index) => {
      const started = performance.now();
      const report = onProgress && ((p) => onProgress(p, index));
      const result = fitMeasured(measured, model, { ...options, samples, onProgress: report });
      onFitted?.(result, index, performance.now() - started);
      return [model, result];
    }),
  );
}
