// @ts-check
// The normal distributions D(n·h) of the microfacet BRDF. evaluate(c, p, s2): s2 = sin²θh when known from the
// half vector itself (h.x² + h.y², precise near n), else taken from c. The ranges are the ones ndf.js clamps to.
// args are fields of the microfacet input (microfacet-input.js) or parameters, each read from its uniform.
import {
  ndfABC,
  ndfBeckmannFromSin2,
  ndfBlinnPhongFromSin2,
  ndfGGXFromSin2,
  ndfSGD,
  clampSgd,
  sgdNormalization,
} from '../ndf.js';
import { ndfBeckmannAniso, ndfGGXAniso } from '../anisotropic.js';
import { ALPHA as alpha, terms } from './term.js';

/** @param {number} c */
const sin2 = (c) => (1 - c) * (1 + c);

const NDF = { definePrefix: 'NDF', chunk: 'ndf.glsl' };

/** Γ(1 - p, alpha) at the clamped parameters (ndfSGD's normaliser), kept for the last pair: a curve asks for one. */
const sgdNormaliser = (() => {
  let last = { alpha: NaN, p: NaN, norm: NaN };
  return (/** @type {number} */ alpha, /** @type {number} */ p) => {
    if (alpha !== last.alpha || p !== last.p) last = { alpha, p, norm: sgdNormalization(...clampSgd(alpha, p)) };
    return last.norm;
  };
})();

/** @type {import('./types.js').TermFamily} */
export const NDF_FAMILY = {
  family: 'ndf',
  label: 'Normal distribution D',
  choice: 'D',
  definePrefix: NDF.definePrefix,
  glslDispatch: 'ndfTerm',
  glslSignature: 'float ndfTerm(MicrofacetInput m)',
  microfacetInput: true,
  defaultKey: 'ggx',
  terms: terms(NDF, {
    ggx: {
      label: 'GGX',
      cite: 'Trowbridge & Reitz 1975; Walter et al. 2007',
      js: ndfGGXFromSin2,
      evaluate: (c, p, s2 = sin2(c)) => ndfGGXFromSin2(c, s2, p.alpha),
      glsl: 'ndfGGXFromSin2',
      args: ['nh', 'sin2h', 'alpha'],
      params: { alpha },
      capabilities: { sampler: 'sampleGGXNormal', dfgTable: true, measuredFit: true },
    },
    beckmann: {
      label: 'Beckmann',
      cite: 'Beckmann & Spizzichino 1963',
      js: ndfBeckmannFromSin2,
      evaluate: (c, p, s2 = sin2(c)) => ndfBeckmannFromSin2(c, s2, p.alpha),
      glsl: 'ndfBeckmannFromSin2',
      args: ['nh', 'sin2h', 'alpha'],
      params: { alpha },
      capabilities: { sampler: 'sampleBeckmannNormal', dfgTable: true, measuredFit: true },
    },
    blinnPhong: {
      label: 'Blinn–Phong',
      cite: 'Blinn 1977',
      js: ndfBlinnPhongFromSin2,
      evaluate: (c, p, s2 = sin2(c)) => ndfBlinnPhongFromSin2(c, s2, p.exponent),
      glsl: 'ndfBlinnPhongFromSin2',
      args: ['nh', 'sin2h', 'exponent'],
      capabilities: { measuredFit: true },
      // 1e30: ndf.glsl's clamp
      params: {
        exponent: {
          min: 0,
          max: 1e30,
          unit: '',
          label: 'Exponent p',
          // not `clamped`: the GLSL clamps at 1e30, the JS at the largest double, so they part past 1e30
          delicate: [1, 10, 100, 1e3, 1e4, 1e6, 2e6, 2e8, 1e12],
          uniform: 'uExponent',
          default: 40,
        },
      },
    },
    abc: {
      label: 'ABC',
      cite: 'Low et al. 2012',
      js: ndfABC,
      evaluate: (c, p) => ndfABC(c, p.a1, p.a2),
      glsl: 'ndfABC',
      args: ['nh', 'a1', 'a2'],
      capabilities: { measuredFit: true },
      params: {
        a1: { min: 0.01, max: 1e4, unit: '', label: 'ABC sharpness a1', clamped: true, uniform: 'uA1', default: 20 },
        a2: {
          min: 0.05,
          max: 20,
          unit: '',
          label: 'ABC shape a2',
          clamped: true,
          delicate: [0.5, 1, 1.5, 2, 3, 10],
          uniform: 'uA2',
          default: 2.5,
        },
      },
    },
    sgd: {
      label: 'Shifted gamma (SGD)',
      short: 'SGD',
      cite: 'Bagher et al. 2012',
      js: ndfSGD,
      evaluate: (c, p) => ndfSGD(c, p.alpha, p.p, sgdNormaliser(p.alpha, p.p)),
      glsl: 'ndfSGD',
      args: ['nh', 'alpha', 'p'],
      // the GLSL's last argument, from the parameters (args after n·h): computed once per draw, not per pixel
      normaliser: sgdNormaliser,
      normaliserUniform: 'uSgdNorm',
      capabilities: { measuredFit: true },
      params: {
        // the shared α (its uniform, its field of the input) over SGD's own, wider range
        alpha: { ...alpha, min: 0.01, max: 2, label: 'SGD width α', delicate: [0.05, 0.2, 0.5, 1] },
        p: {
          min: 0,
          max: 1.9,
          unit: '',
          label: 'SGD shape p',
          clamped: true,
          delicate: [0.3, 0.64, 1, 1.5],
          uniform: 'uSgdP',
          default: 0.64,
        },
      },
    },
    // the anisotropic lobes read the whole input (h in the tangent frame, the α pair): no curve of n·h alone
    ggxAniso: {
      label: 'GGX, anisotropic',
      short: 'GGX aniso.',
      cite: 'Heitz 2014; Burley 2012',
      isotropic: 'ggx',
      js: ndfGGXAniso,
      evaluate: null,
      glsl: 'ndfGGXAniso',
      chunk: 'anisotropic.glsl',
      args: ['hx', 'hy', 'hz', 'alphaX', 'alphaY'],
      params: {}, // αx, αy: the input's fields, over the shared parameters' ranges
    },
    beckmannAniso: {
      label: 'Beckmann, anisotropic',
      short: 'Beckmann aniso.',
      cite: 'Heitz 2014',
      isotropic: 'beckmann',
      js: ndfBeckmannAniso,
      evaluate: null,
      glsl: 'ndfBeckmannAniso',
      chunk: 'anisotropic.glsl',
      args: ['hx', 'hy', 'hz', 'alphaX', 'alphaY'],
      params: {}, // αx, αy: the input's fields, over the shared parameters' ranges
    },
  }),
};
