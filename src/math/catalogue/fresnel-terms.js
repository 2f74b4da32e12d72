// @ts-check
// The Fresnel terms F(l·h) of the microfacet BRDF. Parameters: f0 (Schlick), eta (and k) for the exact forms.
import { fresnelConductor, fresnelDielectric, fresnelSchlick } from '../fresnel.js';
import { PARAMETERS } from './parameters.js';

const { f0 } = PARAMETERS;

/** @type {import('./types.js').TermFamily} */
export const FRESNEL_FAMILY = {
  family: 'fresnel',
  label: 'Fresnel F',
  choice: 'F',
  definePrefix: 'F',
  glslDispatch: 'fresnelTerm',
  glslSignature: 'vec3 fresnelTerm(vec3 f0, float lh)',
  defaultKey: 'schlick',
  terms: {
    one: {
      key: 'one',
      label: 'F = 1',
      short: 'F = 1',
      cite: 'Hoffman 2013',
      js: null, // no factor: the term is switched off
      evaluate: () => 1,
      glsl: null,
      chunk: null,
      define: 'F_ONE',
      glslCall: 'vec3(1.0)',
      args: [],
      params: {},
    },
    schlick: {
      key: 'schlick',
      label: 'Schlick',
      short: 'Schlick',
      cite: 'Schlick 1994',
      js: fresnelSchlick,
      evaluate: (c, p) => fresnelSchlick(p.f0, c),
      glsl: 'fresnelSchlick',
      chunk: 'fresnel.glsl',
      define: 'F_SCHLICK',
      glslCall: 'fresnelSchlick(f0, lh)',
      args: ['f0', 'cos'],
      params: { f0 },
    },
    dielectric: {
      key: 'dielectric',
      label: 'Exact (dielectric)',
      short: 'Exact dielectric',
      cite: 'Fresnel 1823',
      js: fresnelDielectric,
      evaluate: (c, p) => fresnelDielectric(c, p.eta),
      glsl: 'fresnelDielectric',
      chunk: 'fresnel.glsl',
      define: null, // no dispatch offers it yet
      args: ['cos', 'eta'],
      params: {
        eta: {
          min: 1e-3,
          max: 100,
          unit: '',
          label: 'Relative index of refraction η',
          // no interface (η = 1, approached from both sides), total internal reflection, water, glass, diamond
          delicate: [0.5, 1 / 1.5, 0.9, 1 - 1e-3, 1 - 1e-6, 1, 1 + 1e-6, 1 + 1e-3, 1.1, 1.33, 1.5, 2.42, 4],
        },
      },
    },
    conductor: {
      key: 'conductor',
      label: 'Exact (conductor)',
      short: 'Exact conductor',
      cite: 'Lagarde 2013',
      js: fresnelConductor,
      evaluate: (c, p) => fresnelConductor(c, p.eta, p.k),
      glsl: 'fresnelConductor',
      chunk: 'fresnel.glsl',
      define: null, // no dispatch offers it yet
      args: ['cos', 'eta', 'k'],
      params: {
        eta: {
          min: 0.03,
          max: 100,
          unit: '',
          label: 'Relative index of refraction η',
          delicate: [0.2, 0.5, 1, 1 + 1e-6, 1.5, 3, 10],
        },
        k: { min: 0, max: 10, unit: '', label: 'Extinction coefficient k', delicate: [1e-3, 0.5, 1, 2.5, 5] },
      },
    },
  },
};

// F82-tint, appended on its own (issue 29): a metal's Fresnel with a second colour at θ = acos(1/7) ≈ 81.8°. No
// dispatch offers it yet: its tint is not an input of fresnelTerm(f0, lh).
import { fresnelF82Tint } from '../fresnel.js';

/** @type {import('./types.js').TermEntry} */
const F82_TINT = {
  key: 'f82Tint',
  label: 'F82-tint',
  short: 'F82-tint',
  cite: 'Hoffman 2023',
  js: fresnelF82Tint,
  evaluate: (c, p) => fresnelF82Tint(p.f0, p.tint, c),
  glsl: 'fresnelF82Tint',
  chunk: 'fresnel.glsl',
  define: null,
  args: ['f0', 'tint', 'cos'],
  params: {
    f0: { ...f0, clamped: true },
    tint: {
      min: 0,
      max: 1,
      unit: '',
      label: 'Tint at 81.8° (OpenPBR specular_color)',
      clamped: true,
      // the talk's metals (0.77 to 0.99), 0.51 (where clamping to 0 starts at f0 = 0) and no tint
      delicate: [0.3, 0.51, 0.77, 0.9, 0.99],
    },
  },
};
FRESNEL_FAMILY.terms.f82Tint = F82_TINT;
