// The microfacet BRDF f(l, v) = F(l·h) D(n·h) V(l, v) / 4 assembled from named terms, and the punctual
// light equation. Vectors are arrays [x, y, z] in the local frame, n = (0, 0, 1), pointing away from the
// surface. f is 0 when l or v is at or below the horizon, and when l = -v leaves no half vector.
import { CATALOGUE } from './catalogue/index.js';

/**
 * A family's terms as { key: evaluate } (see src/math/catalogue/types.js for each family's arguments): the terms
 * of the cosines alone, so not the anisotropic ones, which read the whole microfacet input.
 */
const evaluators = (family) =>
  Object.fromEntries(
    Object.values(CATALOGUE[family].terms)
      .filter((term) => term.evaluate)
      .map((term) => [term.key, term.evaluate]),
  );

/** Each F term of cos = l·h and the material params { f0, eta, k }. */
export const FRESNEL_TERMS = evaluators('fresnel');

/**
 * Each D term of n·h and the distribution params { alpha, exponent, a1, a2, p }; s2 = sin²θh when known
 * from the half vector itself (h.x² + h.y², precise near n), else from c.
 */
export const NDF_TERMS = evaluators('ndf');

/** Each V term of the cosines { nl, nv, nh, lh } and { alpha }. */
export const VISIBILITY_TERMS = evaluators('visibility');

/** Half vector of l and v, or null when l = -v. */
export function halfVector(l, v) {
  const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]];
  const len = Math.hypot(h[0], h[1], h[2]);
  return len > 1e-12 ? h.map((x) => x / len) : null;
}

/** The cosines a BRDF needs: n·l, n·v, n·h, l·h (h null when l = -v). */
export function brdfAngles(l, v) {
  const h = halfVector(l, v);
  const cos = (x) => Math.min(Math.max(x, -1), 1); // rounding can put a dot product of unit vectors 1 ulp past 1
  return {
    nl: cos(l[2]),
    nv: cos(v[2]),
    nh: h ? cos(h[2]) : 0,
    lh: h ? cos(l[0] * h[0] + l[1] * h[1] + l[2] * h[2]) : 0,
    h,
  };
}

/**
 * Every factor of the microfacet BRDF at (l, v): { F, D, V, G, angles }, with G = V (n·l)(n·v).
 * params: { F, D, V } term names, plus the material and distribution parameters they read.
 */
export function microfacetTerms(l, v, params) {
  return microfacetTermsAt(brdfAngles(l, v), params);
}

/**
 * The same from the cosines alone ({ nl, nv, nh, lh }, as a probe reads them at a surface point); with h
 * given too, D takes sin²θh from it (precise near the mirror direction).
 */
export function microfacetTermsAt(a, params) {
  if (!(a.nl > 0 && a.nv > 0) || a.h === null) return { F: 0, D: 0, V: 0, G: 0, angles: a };
  const F = FRESNEL_TERMS[params.F](a.lh, params);
  const D = NDF_TERMS[params.D](a.nh, params, a.h ? a.h[0] * a.h[0] + a.h[1] * a.h[1] : undefined);
  const V = VISIBILITY_TERMS[params.V](a, params);
  return { F, D, V, G: V * a.nl * a.nv, angles: a };
}

/** f = F D V / 4 from the cosines (see microfacetTermsAt). */
export function microfacetBRDFAt(a, params) {
  const t = microfacetTermsAt(a, params);
  return (t.F * t.D * t.V) / 4;
}

/** f(l, v) = F D V / 4, in 1/sr. */
export function microfacetBRDF(l, v, params) {
  const t = microfacetTerms(l, v, params);
  return (t.F * t.D * t.V) / 4;
}

/** The whole BRDF: specular plus an optional diffuse term diffuse(l, v) (e.g. Lambert, c_diff/pi). */
export function brdf(l, v, params, diffuse = null) {
  if (!(l[2] > 0 && v[2] > 0)) return 0;
  return microfacetBRDF(l, v, params) + (diffuse ? diffuse(l, v) : 0);
}

/** The talk's punctual light: L_o = pi f(l_c, v) c_light (n·l_c), with n·l clamped at 0. */
export function punctualRadiance(f, nl, cLight) {
  return Math.PI * f * cLight * Math.max(nl, 0);
}

/**
 * The BRDF a punctual light's radiance implies, the talk's equation solved for f: f = L_o / (pi c_light (n·l_c)).
 * Null where no light arrives (c_light (n·l) ≤ 0), where L_o says nothing about f.
 */
export function brdfFromPunctualRadiance(radiance, nl, cLight) {
  const arriving = cLight * Math.max(nl, 0);
  return arriving > 0 ? radiance / (Math.PI * arriving) : null;
}

/**
 * The microfacet BRDF with factors switched off for teaching: F·D·G / (4 (n·l)(n·v)) where each factor in
 * `use` ({ F, D, G, denominator }) that is false counts as 1. All on, it equals microfacetBRDF.
 */
export function microfacetFactors(l, v, params, use) {
  const t = microfacetTerms(l, v, params);
  const { nl, nv } = t.angles;
  if (!(nl > 0 && nv > 0) || !t.angles.h) return 0;
  return ((use.F ? t.F : 1) * (use.D ? t.D : 1) * (use.G ? t.G : 1)) / (use.denominator ? 4 * nl * nv : 1);
}
