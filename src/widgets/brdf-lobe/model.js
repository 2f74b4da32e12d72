// The BRDF lobe's numbers, from src/math only: BRDFs A and B as the term choices and matched parameters the
// math reads, their lobes in the plane of incidence with the factors switched on, the multiple-scattering lobe
// and the walk's dots, the (θh, θd) image function, the directional albedo and the factors at (l, v).
import { brdfAngles, microfacetBRDF, microfacetFactors } from '../../math/brdf.js';
import { ndfParamsMatchingGGX } from '../../math/ndf-width.js';
import { directionFromCos, reflectanceImportanceGGX } from '../../math/integrate.js';
import { directionsFromHalfDiff } from '../../math/half-diff.js';
import { DEG } from '../../math/angles.js';
import { termEntry, termLabel } from '../../math/catalogue/index.js';
import { WALK_ANGLES, hasMultipleLobe, kullaContyLobe, walkMultiplePart } from './multiple-lobe.js';

/** The light at θl on the left of n, the view at θv (+: the mirror side), in the plane of incidence (x, z). */
export const lightDir = (deg) => [-Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
export const viewDir = (deg) => [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];

/** The view angles of the lobes in the plane of incidence: −89° to 89° every 0.5°. */
const LOBE_ANGLES = Array.from({ length: 357 }, (_, i) => -89 + i * 0.5);

/** BRDF A or B as microfacetBRDF's params: its terms, the parameters matching GGX's α, and its label. */
export function brdfSpec(state, which) {
  const [D, V, alpha] = which === 'B' ? [state.D2, state.V2, state.alpha2] : [state.D, state.V, state.alpha];
  return {
    D,
    V,
    F: state.F,
    f0: state.f0,
    ...ndfParamsMatchingGGX(D, alpha),
    samplingAlpha: alpha,
    label: `${which}: ${termEntry('ndf', D).short} + ${termLabel('visibility', V)}`,
  };
}

/** [A] or, with the overlay, [A, B]. */
export const brdfSpecs = (state) => [brdfSpec(state, 'A'), ...(state.compare ? [brdfSpec(state, 'B')] : [])];

const factorSwitches = (state) => ({
  F: state.useF,
  D: state.useD,
  G: state.useG,
  denominator: state.useDenominator,
});

/** v ↦ f(l, v) of p with the chosen factors, times n·v when the lobe shows intensity. */
const lobeFunction = (state, l, p) => (v) =>
  microfacetFactors(l, v, p, factorSwitches(state)) * (state.cosine ? Math.max(v[2], 0) : 1);

/** (θh, θd) ↦ f of p with the chosen factors, at the state's φd. */
export const halfDiffFunction = (state, p) => (thetaH, thetaD) => {
  const d = directionsFromHalfDiff(thetaH, thetaD, state.phiD * DEG);
  return microfacetFactors(d.l, d.v, p, factorSwitches(state));
};

/** F0 for the multiple-scattering lobe: 1 when Fresnel is off or F = 1. */
const multipleF0 = (state) => (state.F === 'one' || !state.useF ? 1 : state.f0);
/** Kulla & Conty's f_ms F_ms of A at (l, v), in 1/sr. */
export const kullaContyAt = (state, l, v) => kullaContyLobe(l, v, state.alpha, multipleF0(state));

/** The dotted lobe and the walk's dots when multiple scattering is on (and defined for A), else nulls. */
function multipleScattering(state, A, l) {
  if (!state.multiple || !hasMultipleLobe(A)) return { lobe: null, points: null };
  const f0 = multipleF0(state);
  const weight = (v) => (state.cosine ? Math.max(v[2], 0) : 1);
  const lobe = LOBE_ANGLES.map((theta) => {
    const v = viewDir(theta);
    return [theta, kullaContyLobe(l, v, state.alpha, f0) * weight(v)];
  });
  const points = WALK_ANGLES.map((theta, i) => {
    const v = viewDir(theta);
    const w = walkMultiplePart(l, v, state.alpha, f0, 1 + i);
    return [theta, w.value * weight(v), w.error * weight(v)];
  });
  return { lobe, points };
}

/**
 * Everything the views draw for the state's light and view: l, v, their angles a, the specs A and B (B null
 * without the overlay), fA and fB (v ↦ lobe value), lobeA, lobeB and ms ({ lobe, points }) as [θ, value] in
 * the plane of incidence, and max, the largest value of them all.
 */
export function lobeScene(state) {
  const l = lightDir(state.lightTheta);
  const v = viewDir(state.viewTheta);
  const [A, B = null] = brdfSpecs(state);
  const fA = lobeFunction(state, l, A);
  const fB = B ? lobeFunction(state, l, B) : null;
  const inPlane = (f) => LOBE_ANGLES.map((theta) => [theta, f(viewDir(theta))]);
  const lobeA = inPlane(fA);
  const lobeB = fB ? inPlane(fB) : null;
  const ms = multipleScattering(state, A, l);
  const values = [lobeA, lobeB, ms.lobe, ms.points].flatMap((lobe) => (lobe ?? []).map((x) => x[1]));
  return { l, v, a: brdfAngles(l, v), A, B, fA, fB, lobeA, lobeB, ms, max: Math.max(...values, 1e-9) };
}

/** The [θ, value] of a lobe's largest value. */
export const lobePeak = (lobe) => lobe.reduce((a, x) => (x[1] > a[1] ? x : a));

/** The view angles of the albedo plot (degrees). */
export const ALBEDO_ANGLES = Float64Array.from({ length: 45 }, (_, i) => i * 2 + 1);

/** E(θv) = ∫ f (n·l) dω of p, all factors on, by importance sampling GGX at its α (512 samples). */
export const albedoCurve = (p) =>
  ALBEDO_ANGLES.map((deg) =>
    reflectanceImportanceGGX(
      (l, v) => microfacetBRDF(l, v, p),
      directionFromCos(Math.cos(deg * DEG)),
      p.samplingAlpha,
      512,
    ),
  );

/** F, D, G and f of p at (l, v) with angles a; F, D and G are 1 where f has no half vector or is below. */
export function factorsAt(l, v, a, p) {
  const only = (k) => ({ F: k === 'F', D: k === 'D', G: k === 'G', denominator: false });
  const terms = { F: 1, D: 1, G: 1 };
  if (a.h && a.nl > 0 && a.nv > 0) {
    terms.F = p.F === 'one' ? 1 : microfacetFactors(l, v, p, only('F'));
    terms.D = microfacetFactors(l, v, p, only('D'));
    terms.G = microfacetFactors(l, v, p, only('G'));
  }
  return { ...terms, f: microfacetFactors(l, v, p, { F: true, D: true, G: true, denominator: true }) };
}
