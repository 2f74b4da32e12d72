// @ts-check
// The multiple-scattering compensations (multiple-scattering.js says what each does and cites it). They are not
// factors of f at one (l, v) as the other families' terms are: Kulla–Conty adds a lobe with its own Fresnel
// factor, Turquin scales the whole single-scattering lobe by a factor of its albedo E(n·v). So js and evaluate
// are null; the functions are multipleScatteringKullaConty and energyCompensationTurquin, which the hosts (the
// material lab, the energy widget's furnace) combine with the lobe themselves.

import { PARAMETERS } from './parameters.js';

const { alpha, f0, E } = PARAMETERS;

/** @type {import('./types.js').TermFamily} */
export const COMPENSATION_FAMILY = {
  family: 'compensation',
  label: 'Multiple scattering',
  choice: 'compensation',
  definePrefix: 'COMPENSATION',
  glslDispatch: null,
  defaultKey: 'none',
  terms: {
    none: {
      key: 'none',
      label: 'None (single scattering)',
      short: 'single scattering',
      cite: 'Walter et al. 2007; Heitz 2014',
      js: null,
      evaluate: null,
      glsl: null,
      chunk: null,
      define: null, // single scattering is the lobe without a compensation
      args: [],
      params: {},
    },
    kullaConty: {
      key: 'kullaConty',
      label: 'Kulla–Conty',
      short: 'Kulla–Conty',
      cite: 'Kulla & Conty 2017',
      js: null,
      evaluate: null,
      glsl: 'multipleScatteringKullaConty',
      chunk: 'multiple-scattering.glsl',
      define: 'COMPENSATION_KULLA_CONTY',
      args: ['nl', 'nv', 'alpha'],
      params: { alpha, f0 },
    },
    turquin: {
      key: 'turquin',
      label: 'Turquin',
      short: 'Turquin',
      cite: 'Turquin 2019',
      js: null,
      evaluate: null,
      glsl: 'energyCompensationTurquin',
      chunk: 'multiple-scattering.glsl',
      define: 'COMPENSATION_TURQUIN',
      args: ['f0', 'E'],
      params: { alpha, f0, E },
    },
  },
};
