// @ts-check
// The visibility terms V = G / ((n·l)(n·v)) of the microfacet BRDF. evaluate(a, p): a = { nl, nv, nh, lh }. args
// are fields of the microfacet input (microfacet-input.js).
import {
  visibilityCookTorrance,
  visibilityImplicit,
  visibilityKelemen,
  visibilitySchlickGGX,
  visibilitySmithBeckmannSeparable,
  visibilitySmithGGXCorrelated,
  visibilitySmithGGXCorrelatedFast,
  visibilitySmithGGXSeparable,
} from '../visibility.js';
import { visibilitySmithGGXCorrelatedAniso } from '../anisotropic.js';
import { ALPHA as alpha } from './term.js';

/**
 * A term of roughness alpha whose functions take (nl, nv, alpha) alike (names spelled out: a bundle may
 * rename functions).
 * @param {{ key: string, label: string, short: string, cite: string, define: string }} names
 * @param {(nl: number, nv: number, alpha: number) => number} js
 * @param {string} glsl
 * @param {import('./types.js').TermCapabilities} [capabilities]
 * @returns {import('./types.js').TermEntry}
 */
const smithLike = ({ key, label, short, cite, define }, js, glsl, capabilities) => ({
  key,
  label,
  short,
  cite,
  js,
  evaluate: (a, p) => js(a.nl, a.nv, p.alpha),
  glsl,
  chunk: 'visibility.glsl',
  define,
  args: ['nl', 'nv', 'alpha'],
  params: { alpha },
  ...(capabilities ? { capabilities } : {}),
});

/** @type {import('./types.js').TermFamily} */
export const VISIBILITY_FAMILY = {
  family: 'visibility',
  label: 'Visibility V',
  choice: 'V',
  definePrefix: 'VIS',
  glslDispatch: 'visibilityTerm',
  glslSignature: 'float visibilityTerm(MicrofacetInput m)',
  microfacetInput: true,
  defaultKey: 'smithGGXCorrelated',
  terms: {
    implicit: {
      key: 'implicit',
      label: 'Implicit (V = 1)',
      short: 'Implicit',
      cite: 'Hoffman 2013',
      js: visibilityImplicit,
      evaluate: (a) => visibilityImplicit(a.nl, a.nv),
      glsl: 'visibilityImplicit',
      chunk: 'visibility.glsl',
      define: 'VIS_IMPLICIT',
      args: ['nl', 'nv'],
      params: {},
      capabilities: { dfgTable: true },
    },
    cookTorrance: {
      key: 'cookTorrance',
      label: 'Cook–Torrance',
      short: 'Cook–Torrance',
      cite: 'Cook & Torrance 1982',
      js: visibilityCookTorrance,
      evaluate: (a) => visibilityCookTorrance(a.nl, a.nv, a.nh, a.lh),
      glsl: 'visibilityCookTorrance',
      chunk: 'visibility.glsl',
      define: 'VIS_COOK_TORRANCE',
      args: ['nl', 'nv', 'nh', 'lh'],
      params: {},
      capabilities: { dfgTable: true, measuredFit: true },
    },
    kelemen: {
      key: 'kelemen',
      label: 'Kelemen 1/(l·h)²',
      short: 'Kelemen',
      cite: 'Kelemen & Szirmay-Kalos 2001',
      js: visibilityKelemen,
      // its function takes l·h alone; like every V it is 0 at and below the horizon
      evaluate: (a) => (a.nl > 0 && a.nv > 0 ? visibilityKelemen(a.lh) : 0),
      glsl: 'visibilityKelemen',
      chunk: 'visibility.glsl',
      define: 'VIS_KELEMEN',
      glslCall: 'aboveHorizon(m.nl, m.nv) ? visibilityKelemen(m.lh) : 0.0',
      args: ['lh'],
      params: {},
      capabilities: { dfgTable: true },
    },
    smithGGXSeparable: smithLike(
      {
        key: 'smithGGXSeparable',
        label: 'Smith GGX, separable',
        short: 'Smith GGX sep.',
        cite: 'Smith 1967; Walter et al. 2007',
        define: 'VIS_SMITH_GGX_SEPARABLE',
      },
      visibilitySmithGGXSeparable,
      'visibilitySmithGGXSeparable',
      { dfgTable: true },
    ),
    smithGGXCorrelated: smithLike(
      {
        key: 'smithGGXCorrelated',
        label: 'Smith GGX, height-correlated',
        short: 'Smith GGX corr.',
        cite: 'Heitz 2014',
        define: 'VIS_SMITH_GGX_CORRELATED',
      },
      visibilitySmithGGXCorrelated,
      'visibilitySmithGGXCorrelated',
      { dfgTable: true, measuredFit: true },
    ),
    smithGGXCorrelatedFast: smithLike(
      {
        key: 'smithGGXCorrelatedFast',
        label: 'Hammon 2017 approx.',
        short: 'Hammon',
        cite: 'Hammon 2017',
        define: 'VIS_SMITH_GGX_CORRELATED_FAST',
      },
      visibilitySmithGGXCorrelatedFast,
      'visibilitySmithGGXCorrelatedFast',
    ),
    schlickGGX: smithLike(
      {
        key: 'schlickGGX',
        label: 'Schlick–GGX (k = α/2)',
        short: 'Schlick–GGX',
        cite: 'Schlick 1994; Karis 2013',
        define: 'VIS_SCHLICK_GGX',
      },
      visibilitySchlickGGX,
      'visibilitySchlickGGX',
      { dfgTable: true },
    ),
    smithBeckmannSeparable: smithLike(
      {
        key: 'smithBeckmannSeparable',
        label: 'Smith Beckmann, separable',
        short: 'Smith Beckmann sep.',
        cite: 'Smith 1967; Walter et al. 2007',
        define: 'VIS_SMITH_BECKMANN_SEPARABLE',
      },
      visibilitySmithBeckmannSeparable,
      'visibilitySmithBeckmannSeparable',
      { measuredFit: true },
    ),
    // Λ with the roughness projected on each direction's azimuth: reads l and v in the tangent frame
    smithGGXCorrelatedAniso: {
      key: 'smithGGXCorrelatedAniso',
      label: 'Smith GGX, height-correlated, anisotropic',
      short: 'Smith GGX corr. aniso.',
      cite: 'Heitz 2014',
      isotropic: 'smithGGXCorrelated',
      js: visibilitySmithGGXCorrelatedAniso,
      evaluate: null,
      glsl: 'visibilitySmithGGXCorrelatedAniso',
      chunk: 'anisotropic.glsl',
      define: 'VIS_SMITH_GGX_CORRELATED_ANISO',
      args: ['lx', 'ly', 'lz', 'vx', 'vy', 'vz', 'alphaX', 'alphaY'],
      params: {}, // αx, αy: the input's fields, over the shared parameters' ranges
    },
  },
};
