// @ts-check
// The diffuse terms, in 1/sr. evaluate(nl, nv, cosPhi, p): cosPhi is the cosine of the azimuth between l and v,
// p = { cdiff, f0, sigma }; every term is 0 at and below the horizon. GLSL: diffuseTerm of diffuse-term.glsl.
import {
  diffuseAshikhminShirley,
  diffuseFresnelWeighted,
  diffuseLambert,
  diffuseOrenNayar,
  diffuseOrenNayarQualitative,
} from '../diffuse.js';
import { PARAMETERS } from './parameters.js';
import { terms } from './term.js';

const { cdiff, f0, sigma } = PARAMETERS;
/** @param {number} nl @param {number} nv */
const above = (nl, nv) => nl > 0 && nv > 0;

const DIFFUSE = { definePrefix: 'DIFFUSE', chunk: 'diffuse.glsl' };

/** @type {import('./types.js').TermFamily} */
export const DIFFUSE_FAMILY = {
  family: 'diffuse',
  label: 'Diffuse',
  choice: 'diffuse',
  definePrefix: DIFFUSE.definePrefix,
  glslDispatch: 'diffuseTerm',
  defaultKey: 'lambert',
  terms: terms(DIFFUSE, {
    lambert: {
      label: 'Lambert',
      cite: 'Lambert 1760',
      js: diffuseLambert,
      // its function takes no angles (the reflectance equation's n·l clamps it); as a BRDF it is 0 below
      evaluate: (nl, nv, cosPhi, p) => (above(nl, nv) ? diffuseLambert(p.cdiff) : 0),
      glsl: 'diffuseLambert',
      args: ['cdiff'],
      params: { cdiff },
    },
    fresnelWeighted: {
      label: 'Fresnel-weighted Lambert',
      short: 'Fresnel-weighted',
      cite: 'Hoffman 2013',
      js: diffuseFresnelWeighted,
      evaluate: (nl, nv, cosPhi, p) => diffuseFresnelWeighted(nl, nv, p.f0, p.cdiff),
      glsl: 'diffuseFresnelWeighted',
      args: ['nl', 'nv', 'f0', 'cdiff'],
      params: { cdiff, f0 },
    },
    ashikhminShirley: {
      label: 'Ashikhmin–Shirley',
      cite: 'Ashikhmin & Shirley 2000',
      js: diffuseAshikhminShirley,
      evaluate: (nl, nv, cosPhi, p) => diffuseAshikhminShirley(nl, nv, p.f0, p.cdiff),
      glsl: 'diffuseAshikhminShirley',
      args: ['nl', 'nv', 'f0', 'cdiff'],
      params: { cdiff, f0 },
    },
    orenNayar: {
      label: 'Oren–Nayar (full)',
      short: 'Oren–Nayar',
      cite: 'Oren & Nayar 1994',
      js: diffuseOrenNayar,
      evaluate: (nl, nv, cosPhi, p) => diffuseOrenNayar(nl, nv, cosPhi, p.sigma, p.cdiff),
      glsl: 'diffuseOrenNayar',
      args: ['nl', 'nv', 'cosPhi', 'sigma', 'cdiff'],
      params: { cdiff, sigma },
    },
    orenNayarQualitative: {
      label: 'Oren–Nayar (qualitative)',
      short: 'O–N qualitative',
      cite: 'Oren & Nayar 1994',
      js: diffuseOrenNayarQualitative,
      evaluate: (nl, nv, cosPhi, p) => diffuseOrenNayarQualitative(nl, nv, cosPhi, p.sigma, p.cdiff),
      glsl: 'diffuseOrenNayarQualitative',
      args: ['nl', 'nv', 'cosPhi', 'sigma', 'cdiff'],
      params: { cdiff, sigma },
    },
  }),
};
