// The BRDF lobe's numbers, from src/math only: BRDFs A and B as the term choices and matched parameters the
// math reads, their lobes in the plane of incidence with the factors switched on, the multiple-scattering lobe
// and the walk's dots, the (θh, θd) image function, the directional albedo and the factors at (l, v). A term the
// user wrote in GLSL (A only) arrives as a lookup of values read back from the GPU (custom-tables.js).
import { FRESNEL_TERMS, NDF_TERMS, VISIBILITY_TERMS, brdfAngles } from '../../math/brdf.js';
import { SLOTS } from '../../core/custom/slots.js';
import { ndfParamsMatchingGGX } from '../../math/ndf-width.js';
import { directionFromCos, reflectanceImportanceGGX } from '../../math/integrate.js';
import { directionsFromHalfDiff } from '../../math/half-diff.js';
import { DEG } from '../../math/angles.js';
import { termEntry, termLabel } from '../../math/catalogue/index.js';
import { WALK_ANGLES, hasMultipleLobe, kullaContyLobe, walkMultiplePart } from './multiple-lobe.js';
import { anisotropicAlphas } from '../../math/anisotropic.js';
import { microfacetInput, termAt } from '../../math/catalogue/microfacet-input.js';
import { anisotropicForm } from '../../math/catalogue/anisotropic-forms.js';
import { LAYER_KEYS, layerLuminances, openPbrAlbedo, openPbrSpec, openPbrValue } from './openpbr-lobe.js';
import { planeAzimuth, turnAboutN } from './azimuths.js';

/**
 * A's anisotropic lobe, when its anisotropy is above 0 and its D has an anisotropic form in the catalogue
 * (anisotropic-forms.js): { D, V (the forms' keys; V null: it stays isotropic at α), pair [αx, αy], phi (the plane
 * of incidence's azimuth from the tangent, radians) }; else null.
 */
export function anisotropyOf(state, D, V) {
  const stretched = anisotropicForm('ndf', D);
  if (!(state.anisotropy > 0) || !stretched) return null;
  return {
    D: stretched.key,
    V: anisotropicForm('visibility', V)?.key ?? null,
    pair: anisotropicAlphas(state.alpha, state.anisotropy, state.convention),
    phi: planeAzimuth(state),
  };
}

/** The light at θl on the left of n, the view at θv (+: the mirror side), in the plane of incidence (x, z). */
export const lightDir = (deg) => [-Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
export const viewDir = (deg) => [Math.sin(deg * DEG), 0, Math.cos(deg * DEG)];
/** The state's view, turned off the plane of incidence by its Δφ. */
export const viewOf = (state) => turnAboutN(viewDir(state.viewTheta), state.viewPhi * DEG);

/** The view angles of the lobes in the plane of incidence: −89° to 89° every 0.5°. */
const LOBE_ANGLES = Array.from({ length: 357 }, (_, i) => -89 + i * 0.5);

/** The view angles of the albedo plot (degrees). */
export const ALBEDO_ANGLES = Float64Array.from({ length: 45 }, (_, i) => i * 2 + 1);

/** The slots of A the user wrote (the whole BRDF, or any of D, V, F). */
export const customSlots = (state) =>
  state.brdf === 'custom'
    ? ['brdf']
    : state.brdf === 'openpbr'
      ? []
      : ['D', 'V', 'F'].filter((k) => state[k] === 'custom');

/** The catalogue term a custom slot stands in for before any code of it has run (the starter's term). */
const standIn = (slotKey, term) => (term === 'custom' ? SLOTS[slotKey].reference : term);

function specLabel(state, which, D, V) {
  if (which === 'A' && state.brdf === 'custom') return 'A: your BRDF';
  const d = D === 'custom' ? 'your D' : termEntry('ndf', D).short;
  const v = V === 'custom' ? 'your V' : termLabel('visibility', V);
  return `${which}: ${d} + ${v}${which === 'A' && state.F === 'custom' ? ' + your F' : ''}`;
}

/**
 * BRDF A or B as the math reads it: its terms, the parameters matching GGX's α, and its label; `custom` holds A's
 * lookups of user-written terms ({ D, V, F, brdf }, each absent until its code has run).
 */
export function brdfSpec(state, which, custom = {}) {
  const B = which === 'B';
  if (!B && state.brdf === 'openpbr') return openPbrSpec(state);
  const [D, V, alpha] = B ? [state.D2, state.V2, state.alpha2] : [state.D, state.V, state.alpha];
  const own = B
    ? {}
    : Object.fromEntries(
        customSlots(state)
          .map((k) => [k, custom[k]])
          .filter(([, f]) => f),
      );
  const F = B && state.F === 'custom' ? SLOTS.F.reference : state.F;
  const aniso = B || state.brdf === 'custom' ? null : anisotropyOf(state, D, V);
  return {
    D: standIn('D', D),
    V: standIn('V', V),
    F: standIn('F', F),
    f0: state.f0,
    ...ndfParamsMatchingGGX(standIn('D', D), alpha),
    samplingAlpha: alpha,
    aniso,
    custom: !B && state.brdf === 'custom' ? { brdf: own.brdf ?? LAMBERT_STAND_IN } : own,
    label: aniso ? specLabel(state, which, aniso.D, aniso.V ?? V) : specLabel(state, which, D, V),
  };
}

/** A whole custom BRDF before its code has run: the starter's Lambert at albedo 1, f = 1/π. */
const LAMBERT_STAND_IN = {
  atView: (v) => (v[2] > 0 ? 1 / Math.PI : 0),
  halfDiff: () => 1 / Math.PI,
  albedo: Array.from(ALBEDO_ANGLES, () => 1),
};

/** [A] or, with the overlay, [A, B]. */
const brdfSpecs = (state, custom = {}) => [
  brdfSpec(state, 'A', custom),
  ...(state.compare ? [brdfSpec(state, 'B', custom)] : []),
];

/**
 * F, D, V at (l, v) with cosines a (and a.h), each from its lookup when the user wrote it, else from the catalogue;
 * an anisotropic D and V read l and v turned into the tangent frame.
 */
function termsAt(l, v, a, p) {
  const c = p.custom ?? {};
  const m = p.aniso && microfacetInput(turnAboutN(l, p.aniso.phi), turnAboutN(v, p.aniso.phi), p.aniso.pair);
  const isoD = () => NDF_TERMS[p.D](a.nh, p, a.h[0] * a.h[0] + a.h[1] * a.h[1]);
  const D = c.D ? c.D(a) : m ? termAt(termEntry('ndf', p.aniso.D), m, {}) : isoD();
  const anisoV = m && p.aniso.V;
  const V = c.V ? c.V(a) : anisoV ? termAt(termEntry('visibility', anisoV), m, {}) : VISIBILITY_TERMS[p.V](a, p);
  return { F: c.F ? c.F(a) : FRESNEL_TERMS[p.F](a.lh, p), D, V, G: V * a.nl * a.nv };
}

const ALL_FACTORS = { F: true, D: true, G: true, denominator: true };

/**
 * f(l, v) of p with the factors in `use` ({ F, D, G, denominator }) that are false counted as 1, as
 * microfacetFactors of src/math/brdf.js; a whole custom BRDF has no factors to switch.
 */
export function factorsOf(l, v, p, use = ALL_FACTORS) {
  if (p.custom?.brdf) return p.custom.brdf.atView(v);
  if (p.openpbr) return openPbrValue(l, v, p);
  const a = brdfAngles(l, v);
  if (!(a.nl > 0 && a.nv > 0) || !a.h) return 0;
  const t = termsAt(l, v, a, p);
  return ((use.F ? t.F : 1) * (use.D ? t.D : 1) * (use.G ? t.G : 1)) / (use.denominator ? 4 * a.nl * a.nv : 1);
}

const factorSwitches = (state) => ({
  F: state.useF,
  D: state.useD,
  G: state.useG,
  denominator: state.useDenominator,
});

/** v ↦ f(l, v) of p with the chosen factors, times n·v when the lobe shows intensity. */
const lobeFunction = (state, l, p) => (v) =>
  factorsOf(l, v, p, factorSwitches(state)) * (state.cosine ? Math.max(v[2], 0) : 1);

/** (θh, θd) ↦ f of p with the chosen factors, at the state's φd. */
export const halfDiffFunction = (state, p) => (thetaH, thetaD) => {
  if (p.custom?.brdf) return p.custom.brdf.halfDiff(thetaH, thetaD);
  const d = directionsFromHalfDiff(thetaH, thetaD, state.phiD * DEG);
  return factorsOf(d.l, d.v, p, factorSwitches(state));
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
export function lobeScene(state, custom = {}) {
  const l = lightDir(state.lightTheta);
  const v = viewOf(state);
  const [A, B = null] = brdfSpecs(state, custom);
  const fA = lobeFunction(state, l, A);
  const fB = B ? lobeFunction(state, l, B) : null;
  const inPlane = (f) => LOBE_ANGLES.map((theta) => [theta, f(viewDir(theta))]);
  const lobeA = inPlane(fA);
  const lobeB = fB ? inPlane(fB) : null;
  const ms = multipleScattering(state, A, l);
  const values = [lobeA, lobeB, ms.lobe, ms.points].flatMap((lobe) => (lobe ?? []).map((x) => x[1]));
  const layers = A.openpbr ? openPbrLayerLobes(state, l, A) : null;
  const scene = { l, v, a: brdfAngles(l, v), A, B, fA, fB, lobeA, lobeB, ms, max: Math.max(...values, 1e-9) };
  return { ...scene, layers };
}

/**
 * A's layers in OpenPBR mode: { parts: [{ key, lobe }] in the plane (each layer's part of A's lobe, none when
 * they are not shown), fLayer (v ↦ the part of the layer the 3-D view draws as a wire grid, or null) }.
 */
function openPbrLayerLobes(state, l, A) {
  const weight = (v) => (state.cosine ? Math.max(v[2], 0) : 1);
  const fLayer = state.openpbrLayer === 'none' ? null : (v) => openPbrValue(l, v, A, state.openpbrLayer) * weight(v);
  if (!state.openpbrParts) return { parts: [], fLayer };
  const values = LOBE_ANGLES.map((theta) => [theta, layerLuminances(l, viewDir(theta), A), weight(viewDir(theta))]);
  const parts = LAYER_KEYS.map((key) => ({ key, lobe: values.map(([theta, y, w]) => [theta, y[key] * w]) }));
  return { parts, fLayer };
}

/** The [θ, value] of a lobe's largest value. */
export const lobePeak = (lobe) => lobe.reduce((a, x) => (x[1] > a[1] ? x : a));

/**
 * E(θv) = ∫ f (n·l) dω of p, all factors on, by importance sampling GGX at its α (512 samples), the view turned
 * off the plane by `turn` (radians; an anisotropic A's albedo depends on it); a whole custom BRDF brings its own
 * (a quadrature on the GPU's values, custom-tables.js).
 */
export const albedoCurve = (p, turn = 0) =>
  p.custom?.brdf?.albedo ??
  (p.openpbr && openPbrAlbedo(p, ALBEDO_ANGLES, turn)) ??
  ALBEDO_ANGLES.map((deg) => {
    const v = turnAboutN(directionFromCos(Math.cos(deg * DEG)), turn);
    return reflectanceImportanceGGX((l, w) => factorsOf(l, w, p), v, p.samplingAlpha, 512);
  });

/**
 * F, D, G and f of p at (l, v) with angles a; F, D and G are 1 where f has no half vector or is below, and null
 * for a whole custom BRDF (it has no factors).
 */
export function factorsAt(l, v, a, p) {
  if (p.custom?.brdf || p.openpbr) return { F: null, D: null, G: null, f: factorsOf(l, v, p) };
  const terms = a.h && a.nl > 0 && a.nv > 0 ? termsAt(l, v, a, p) : { F: 1, D: 1, G: 1 };
  return { F: p.F === 'one' ? 1 : terms.F, D: terms.D, G: terms.G, f: factorsOf(l, v, p) };
}
