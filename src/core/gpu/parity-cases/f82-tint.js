// Parity rows of F82-tint (src/math/fresnel.js) beyond the catalogue's own row (fresnelF82Tint over its stress
// grid): the vec3 twin, the fit to a conductor, and the five measured metals' fitted values near grazing, where
// (1 − μ)⁶ and the subtraction from Schlick meet. Row format: src/core/gpu/parity-cases.js.
import { f82TintFromConductor, fresnelF82Tint } from '../../../math/fresnel.js';
import { METALS } from '../../../math/materials.js';
import { measuredRgbNk } from '../../../math/optical-constants.js';

const cartesian = (...lists) => lists.reduce((acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);

// cos θ: the ends, just beyond them, grazing, μ̄ = 1/7 and its neighbours, the mid angles where the dip is widest
const COS = [-0.5, 0, 1e-7, 1e-4, 0.01, 0.05, 0.1, 1 / 7, 0.15, 0.2, 0.3, 0.5, 0.7071, 0.9, 0.999, 1, 1 + 1e-6];
const F0 = [-0.5, 0, 0.04, 0.3, 0.56, 0.9, 0.99, 1, 1.5];
const TINT = [-0.5, 0, 0.3, 0.51, 0.77, 0.95, 1, 1.5];
// the fresnelConductor parity grid's eta and k (parity-cases.js, GRIDS.etaConductor and GRIDS.k)
const ETA = [0.03, 0.2, 0.5, 1, 1 + 1e-6, 1.5, 3, 10, 100];
const K = [0, 1e-3, 0.5, 1, 2.5, 5, 10];

const METAL_FITS = METALS.flatMap((m) =>
  measuredRgbNk(m.key).map(([eta, k]) => {
    const { f0, tint } = f82TintFromConductor(eta, k);
    return [f0, tint];
  }),
);

export const F82_TINT_PARITY_CASES = [
  {
    name: 'fresnelF82Tint (vec3)',
    chunk: 'fresnel.glsl',
    glsl: 'fresnelF82Tint(vec3(a.x, 0.5 * a.x, 1.0 - a.x), vec3(a.y, 1.0, 0.5 * a.y), a.z)',
    outputs: 3,
    js: (f0, tint, c) =>
      [
        [f0, tint],
        [0.5 * f0, 1],
        [1 - f0, 0.5 * tint],
      ].map(([f, t]) => fresnelF82Tint(Math.fround(f), Math.fround(t), c)),
    range: [0, 1],
    args: cartesian(F0, TINT, COS),
  },
  {
    name: 'fresnelF82Tint (the five metals, fitted)',
    chunk: 'fresnel.glsl',
    glsl: 'fresnelF82Tint(a.x, a.y, a.z)',
    outputs: 1,
    js: fresnelF82Tint,
    range: [0, 1],
    args: METAL_FITS.flatMap(([f0, tint]) => COS.map((c) => [f0, tint, c])),
  },
  {
    // tint = F(1/7) / Schlick(f0, 1/7), at most 1 / (6/7)⁵ ≈ 2.16 (total internal reflection at η < 1)
    name: 'f82TintFromConductor',
    chunk: 'fresnel.glsl',
    glsl: 'f82TintFromConductor(a.x, a.y)',
    outputs: 2,
    js: (eta, k) => {
      const { f0, tint } = f82TintFromConductor(eta, k);
      return [f0, tint];
    },
    range: [0, 2.2],
    args: cartesian(ETA, K),
  },
];
