// What the parity harness checks: each GLSL function against its float64 JS twin, over a grid that
// includes the stress inputs (cos = 0, 1e-7, 1 and just above 1, eta near 1, total internal reflection,
// large k, alpha down to 0, sRGB values outside [0, 1]).
import * as M from '../../math/index.js';
import { CATALOGUE, termDefines } from '../../math/catalogue/index.js';
import { termInputs } from '../../math/catalogue/grids.js';
import { dispatchParityCases } from './parity-cases/dispatch-cases.js';
import { merlCoordinates } from '../../math/merl-coordinates.js';
import { buildAlbedoTableGGX, albedoLossTableGGX } from '../../math/albedo-table.js';
import { ANISOTROPIC_PARITY_CASES } from './parity-cases/anisotropic.js';
import { F82_TINT_PARITY_CASES } from './parity-cases/f82-tint.js';
import { OPENPBR_PARITY_CASES } from './parity-cases/openpbr.js';

let albedoTable = null; // built on first use (~0.5 s)
const albedoTableOnce = () => (albedoTable ??= buildAlbedoTableGGX());
const TABLE_CASE = {
  chunk: 'multiple-scattering.glsl',
  defines: { ALBEDO_TABLE_GGX: 1 },
  tables: { uAlbedoTableGGX: albedoTableOnce },
};

const uniform = (n, lo, hi) => Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));

export const GRIDS = {
  cos: [
    -0.5,
    0,
    1e-7,
    1e-6,
    1e-4,
    1e-3,
    0.01,
    0.1,
    0.2588,
    0.5,
    0.7071,
    0.9,
    0.99,
    0.999,
    0.9999,
    1 - 1e-6,
    1,
    1 + 1e-6,
    ...uniform(25, 0.02, 0.98),
  ],
  theta: [0, 1e-4, 0.3, 0.7854, 1.2, 1.5, 1.5707, Math.PI / 2],
  cosCoarse: [-0.5, 0, 1e-7, 1e-4, 0.01, 0.1, 0.3, 0.5, 0.7071, 0.9, 0.999, 1, 1 + 1e-6],
  eta: [1e-3, 0.5, 1 / 1.5, 0.9, 1 - 1e-3, 1 - 1e-6, 1, 1 + 1e-6, 1 + 1e-3, 1.1, 1.33, 1.5, 2.42, 4, 100],
  etaConductor: [0.03, 0.2, 0.5, 1, 1 + 1e-6, 1.5, 3, 10, 100],
  k: [0, 1e-3, 0.5, 1, 2.5, 5, 10],
  f0: [0, 0.02, 0.04, 0.17, 0.5, 0.95, 1],
  alpha: [0, 1e-5, 1e-4, 1e-3, 0.01, 0.1, 0.3, 0.5, 1],
  exponent: [0, 1, 10, 100, 1e3, 1e4, 1e6, 2e6, 2e8, 1e12, 1e30], // up to the GLSL clamp (ndf.glsl)
  abcA1: [0, 0.01, 0.1, 1, 10, 100, 1e3, 1e4, 2e4],
  abcA2: [0, 0.05, 0.5, 1, 1.5, 2, 3, 10, 20],
  sgdAlpha: [0, 0.01, 0.05, 0.2, 0.5, 1, 2, 3],
  sgdP: [-1, 0, 0.3, 0.64, 1, 1.5, 1.9, 3],
  srgb: [-0.5, 0, 1e-4, 0.003, 0.0031308, 0.04, 0.04045, 0.1, 0.25, 0.5, 0.75, 0.9, 1, 1.5],
};

/**
 * Tolerance: a GPU value g passes against the JS value j when |g - j| <= ATOL + RTOL·|j|.
 * float32 carries ~7 digits; the functions here lose at most a few ulps, and RTOL covers the large
 * values of D near alpha = 1e-4 (about 3e7).
 */
export const TOLERANCE = { atol: 1e-5, rtol: 1e-4 };
const TRIG_TOLERANCE = { atol: 3e-4, rtol: 1e-4 };

const unitDir = (x, y, z) => [x, y, z].map((c) => Math.fround(c / Math.hypot(x, y, z)));
// unit directions for the sphere light: along n, grazing, and two oblique ones (the ray meets the light or not)
const LIGHT_DIRS = [
  [0, 0, 1],
  [1, 0, 1e-4],
  [0.6, 0, 0.8],
  [-0.3, 0.4, 0.866],
].map((d) => unitDir(...d));

const spherical = (theta, phi) =>
  unitDir(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));

const cartesian = (...lists) => lists.reduce((acc, list) => acc.flatMap((a) => list.map((x) => [...a, x])), [[]]);

// Each term of the catalogue with a JS and a GLSL function is one row, named by its GLSL function: its
// parameters swept over their stress values (src/math/catalogue/grids.js), its angles over these.
const THETA_SIN2 = [0, 1e-9, 1e-6, 1e-4, 0.01, 0.3, 1, 1.5, Math.PI / 2]; // half vectors: (cos θ, sin²θ)
// directions of the microfacet input (an anisotropic term's h, l, v): along n, near it, oblique, grazing, at
// azimuths along t, along b and between; l and v also below the horizon
const DIR_THETAS = [0, 1e-4, 0.3, 0.7854, 1.2, 1.5707];
const DIR_PHIS = [0, 0.5, Math.PI / 2, 2.5];
const directions = (thetas, phis, below) => [
  ...cartesian(thetas, phis).map(([t, p]) => spherical(t, p)),
  ...(below ? [unitDir(0.6, 0.2, -0.3)] : []),
];
const termAngles = (kind, dims) => {
  if (kind === 'theta') return THETA_SIN2;
  if (kind === 'cosPhi') return [-1, -0.5, 0, 0.5, 1];
  if (kind.startsWith('dir:')) {
    const coarse = dims > 3;
    return directions(coarse ? [0, 0.3, 1.2, 1.5707] : DIR_THETAS, coarse ? [0, 1] : DIR_PHIS, kind !== 'dir:h');
  }
  return dims > 3 ? GRIDS.cosCoarse : GRIDS.cos;
};
const GRAZING = [1e-7, 3e-7, 1e-6, 1e-5, 1e-4, 1e-3, 0.01, 0.05];
const BITS_U = 'uniformFromBits((uint(a.x) << 16u) | uint(a.y))';
const TINY_COS = [1e-9, 1e-12, 1e-15, 1e-20, 1e-30];
const SLOTS = ['a.x', 'a.y', 'a.z', 'a.w', 'b.x', 'b.y', 'b.z', 'b.w'];
/** The first n inputs of a row in GLSL: a.xyzw, b.xyzw, then arg(8), arg(9), … (parity.frag.glsl). */
const slots = (n) => Array.from({ length: n }, (_, i) => SLOTS[i] ?? `arg(${i})`);
const FAMILY_RANGE = { fresnel: [0, 1], ndf: [0, Infinity], visibility: [0, Infinity], diffuse: [0, Infinity] };
/** Tighter bounds some terms keep (a diffuse albedo at most c, the implicit V at most 1). */
const TERM_RANGE = {
  visibilityImplicit: [0, 1],
  diffuseLambert: [0, 1 / Math.PI],
  diffuseFresnelWeighted: [0, 1 / Math.PI],
  diffuseAshikhminShirley: [0, 28 / (23 * Math.PI)],
};
/**
 * The full Oren–Nayar needs the angles themselves, (4ab/pi²)², times tan up to 1e7 at cos = 1e-7: there the
 * GPU's atan (a polynomial, 2e-5 relative on llvmpipe) sets the accuracy, not the formula.
 */
const TERM_TOLERANCE = { diffuseOrenNayar: { atol: 1e-5, rtol: 5e-4 } };

/** Each tuple with the term's normaliser (of its parameters, after cos) appended, as both twins take it. */
const withNormaliser = (term, tuples) =>
  term.normaliser ? tuples.map(([c, ...params]) => [c, ...params, term.normaliser(...params)]) : tuples;

/** The parity rows of the catalogue's terms. */
export function termParityCases(catalogue) {
  return Object.values(catalogue).flatMap((family) =>
    Object.values(family.terms)
      .filter((term) => term.js && term.glsl)
      .map((term) => ({
        name: term.glsl,
        chunk: term.chunk,
        glsl: `${term.glsl}(${slots(term.args.length + (term.normaliser ? 1 : 0)).join(', ')})`,
        outputs: 1,
        js: term.js,
        range: TERM_RANGE[term.glsl] ?? FAMILY_RANGE[family.family],
        args: withNormaliser(term, termInputs(term, termAngles)),
        ...(TERM_TOLERANCE[term.glsl] ? { tolerance: TERM_TOLERANCE[term.glsl] } : {}),
      })),
  );
}

/**
 * { name, chunk, glsl (expression over a.xyzw, b.xyzw and arg(i) for any input i), outputs, js(...args) -> number |
 * number[], range, args (tuples of any length), prelude? (GLSL after the chunk: helpers the expression calls) }
 */
export const PARITY_CASES = [
  {
    name: 'srgbToLinear',
    chunk: 'color.glsl',
    glsl: 'srgbToLinear(a.x)',
    outputs: 1,
    js: M.srgbToLinear,
    range: [0, 1],
    args: cartesian(GRIDS.srgb),
  },
  {
    name: 'linearToSrgb',
    chunk: 'color.glsl',
    glsl: 'linearToSrgb(a.x)',
    outputs: 1,
    js: M.linearToSrgb,
    range: [0, 1],
    args: cartesian(GRIDS.srgb),
  },
  {
    name: 'fresnelSchlickSG',
    chunk: 'fresnel.glsl',
    glsl: 'fresnelSchlickSG(a.x, a.y)',
    outputs: 1,
    js: M.fresnelSchlickSG,
    range: [0, 1],
    args: cartesian(GRIDS.f0, GRIDS.cos),
  },
  {
    name: 'fresnelSchlick (vec3)',
    chunk: 'fresnel.glsl',
    glsl: 'fresnelSchlick(vec3(a.x, 0.5 * a.x, 1.0 - a.x), a.y)',
    outputs: 3,
    js: (f0, c) => [f0, 0.5 * f0, 1 - f0].map((x) => M.fresnelSchlick(Math.fround(x), c)),
    range: [0, 1],
    args: cartesian(GRIDS.f0, GRIDS.cos),
  },
  {
    name: 'fresnelConductor (vec3)',
    chunk: 'fresnel.glsl',
    glsl: 'fresnelConductor(a.x, vec3(a.y, 1.0, 0.5), vec3(a.z, 2.0, 3.0))',
    outputs: 3,
    js: (c, eta, k) => [M.fresnelConductor(c, eta, k), M.fresnelConductor(c, 1, 2), M.fresnelConductor(c, 0.5, 3)],
    range: [0, 1],
    args: cartesian(GRIDS.cos, GRIDS.etaConductor, GRIDS.k),
  },
  {
    // l and v given as the same float32 vectors to both sides (a.xyz, b.xyz); alpha in a.w. The grid has
    // l = v (phi = 0, equal thetas), mirror pairs (phi = pi), grazing pairs and l = -v at the horizon, with
    // alpha down to 0. It holds because D takes sin²θh from h.xy: from cos θh (which rounds to 1 within
    // 3e-4 rad of n in float32) the relative error reached 2.7e-4 at alpha = 0.01.
    name: 'microfacetBRDF (GGX, Smith corr., Schlick)',
    chunk: 'brdf.glsl',
    defines: termDefines({ F: 'schlick', D: 'ggx', V: 'smithGGXCorrelated' }),
    glsl: 'microfacetBRDF(a.xyz, b.xyz, a.w, 0.04)',
    outputs: 1,
    js: (lx, ly, lz, alpha, vx, vy, vz) =>
      M.microfacetBRDF([lx, ly, lz], [vx, vy, vz], {
        F: 'schlick',
        D: 'ggx',
        V: 'smithGGXCorrelated',
        alpha,
        f0: 0.04,
      }),
    range: [0, Infinity],
    args: cartesian(GRIDS.theta, GRIDS.theta, [0, 1, Math.PI / 2, 3, Math.PI], GRIDS.alpha).map(
      ([tl, tv, phi, alpha]) => [
        Math.sin(tl),
        0,
        Math.cos(tl),
        alpha,
        Math.sin(tv) * Math.cos(phi),
        Math.sin(tv) * Math.sin(phi),
        Math.cos(tv),
        0,
      ],
    ),
  },
  {
    name: 'fresnelAverage',
    chunk: 'multiple-scattering.glsl',
    glsl: 'fresnelAverage(a.x)',
    outputs: 1,
    js: M.fresnelAverage,
    range: [0, 1],
    args: cartesian(GRIDS.f0),
  },
  {
    name: 'fresnelAverage (vec3)',
    chunk: 'multiple-scattering.glsl',
    glsl: 'fresnelAverage(vec3(a.x, 0.5 * a.x, 1.0 - a.x))',
    outputs: 3,
    js: (f0) => [f0, 0.5 * f0, 1 - f0].map((x) => M.fresnelAverage(Math.fround(x))),
    range: [0, 1],
    args: cartesian(GRIDS.f0),
  },
  {
    name: 'fresnelMultipleScatteringKullaConty',
    chunk: 'multiple-scattering.glsl',
    glsl: 'fresnelMultipleScatteringKullaConty(a.x, a.y)',
    outputs: 1,
    // F_avg = 1 and E_avg = 1e-7 together: the textbook denominator 1 - F_avg (1 - E_avg) gave 0.84 instead of 1
    js: M.fresnelMultipleScatteringKullaConty,
    range: [0, 1],
    args: cartesian(GRIDS.f0, [0, 1e-7, 0.3, 0.41, 0.9, 0.9999, 1]),
  },
  {
    name: 'energyCompensationTurquin',
    chunk: 'multiple-scattering.glsl',
    glsl: 'energyCompensationTurquin(a.x, a.y)',
    outputs: 1,
    js: M.energyCompensationTurquin,
    range: [1, 1e4],
    args: cartesian(GRIDS.f0, [-0.5, 0, 1e-7, 1e-4, 0.3, 0.7, 0.9999, 1, 1.5]),
  },
  {
    name: 'multipleScatteringFromLoss',
    chunk: 'multiple-scattering.glsl',
    glsl: 'multipleScatteringFromLoss(a.x, a.y, a.z)',
    outputs: 1,
    js: M.multipleScatteringFromLoss,
    range: [0, Infinity],
    args: cartesian(GRIDS.cosCoarse, GRIDS.cosCoarse, [-1, 0, 1e-7, 1e-4, 0.3, 0.59, 1, 1.5]),
  },
  // the table functions against the JS lookup of the same table (same bilinear rule); the table against the
  // float64 functions is unit-tested (tests/unit/albedo-table.test.js)
  {
    ...TABLE_CASE,
    name: 'albedoLossTableGGX',
    glsl: 'albedoLossTableGGX(a.x, a.y)',
    outputs: 3,
    js: (mu, alpha) => albedoLossTableGGX(albedoTableOnce(), mu, alpha),
    range: [0, 1],
    args: cartesian(GRIDS.cos, GRIDS.alpha),
  },
  {
    ...TABLE_CASE,
    name: 'averageAlbedoGGX (table)',
    glsl: 'averageAlbedoGGX(a.x)',
    outputs: 1,
    range: [0, 1],
    args: cartesian(GRIDS.alpha),
    js: (alpha) => 1 - albedoLossTableGGX(albedoTableOnce(), 1, alpha)[1],
  },
  ...[
    ['specularAlbedoGGX', 'none'],
    ['specularAlbedoKullaConty', 'kullaConty'],
    ['specularAlbedoTurquin', 'turquin'],
  ].map(([name, compensation]) => ({
    ...TABLE_CASE,
    name,
    glsl: `${name}(a.x, a.y, a.z)`,
    outputs: 1,
    range: [0, 1],
    args: cartesian(GRIDS.cosCoarse, GRIDS.alpha, GRIDS.f0),
    js: (mu, alpha, f0) => M.specularAlbedoFromTable(albedoTableOnce(), mu, alpha, f0, compensation),
  })),
  {
    ...TABLE_CASE,
    name: 'multipleScatteringKullaConty (table)',
    glsl: 'multipleScatteringKullaConty(a.x, a.y, a.z)',
    outputs: 1,
    js: (nl, nv, alpha) => {
      if (!(nl > 0 && nv > 0)) return 0;
      const [[lossL], [lossV, lossAvg]] = [nl, nv].map((mu) => albedoLossTableGGX(albedoTableOnce(), mu, alpha));
      return M.multipleScatteringFromLoss(lossL, lossV, lossAvg);
    },
    range: [0, Infinity],
    args: cartesian(GRIDS.cosCoarse, GRIDS.cosCoarse, GRIDS.alpha),
  },
  // directions built from sin and cos of an angle: there the GPU's own sin and cos set the accuracy (SwiftShader's
  // are up to ~1.8e-4 off; hardware's ~1e-6), not the formulas
  {
    name: 'sampleCosine',
    chunk: 'integrate.glsl',
    glsl: 'sampleCosine(a.xy)',
    outputs: 3,
    js: M.sampleCosine,
    range: [-1, 1],
    args: cartesian([0, 1e-6, 0.3, 0.999, 1], [0, 0.25, 0.7]),
    tolerance: TRIG_TOLERANCE,
  },
  {
    name: 'dfgTableUv',
    chunk: 'integrate.glsl',
    glsl: 'dfgTableUv(a.x, a.y)',
    outputs: 2,
    js: M.dfgTableUv,
    range: [0, 1],
    args: cartesian(GRIDS.cosCoarse, GRIDS.alpha),
  },
  // u1 up to 1 - 1e-6 (the samplers take u1 in [0, 1)), alpha from the clamp to 1
  ...['sampleGGXNormal', 'sampleBeckmannNormal'].map((fn) => ({
    name: fn,
    chunk: 'integrate.glsl',
    glsl: `${fn}(a.xy, a.z)`,
    outputs: 3,
    js: M[fn],
    range: [-1, 1],
    args: cartesian([0, 1e-6, 0.3, 0.9, 0.999, 1 - 1e-6], [0, 0.25, 0.7], [0, 1e-4, 0.01, 0.3, 1]),
    tolerance: TRIG_TOLERANCE,
  })),
  {
    name: 'sampleCone',
    chunk: 'integrate.glsl',
    glsl: 'sampleCone(a.xy, a.z)',
    outputs: 3,
    js: M.sampleCone,
    range: [-1, 1],
    args: cartesian([0, 0.3, 1], [0, 0.25, 0.7], [-1, 0, 0.9, 0.99999, 1]),
    tolerance: TRIG_TOLERANCE,
  },
  {
    name: 'sphereLightCLight',
    chunk: 'lighting.glsl',
    glsl: 'sphereLightCLight(a.x, a.y)',
    outputs: 1,
    js: M.sphereLightCLight,
    range: [0, Infinity],
    args: cartesian([0, 1, 500], [0, 1e-4, 0.035, 0.5, 1]),
  },
  {
    name: 'sphereLightRepresentativeDir',
    chunk: 'lighting.glsl',
    glsl: 'sphereLightRepresentativeDir(a.xyz, b.xyz, b.w)',
    outputs: 3,
    js: (rx, ry, rz, _, dx, dy, dz, s) => M.sphereLightRepresentativeDir([rx, ry, rz], [dx, dy, dz], s),
    range: [-1, 1],
    args: cartesian(LIGHT_DIRS, LIGHT_DIRS, [0, 1e-4, 0.05, 0.5]).map(([r, d, s]) => [...r, 0, ...d, s]),
  },
  {
    name: 'sphereLightNormalization',
    chunk: 'lighting.glsl',
    glsl: 'sphereLightNormalization(a.x, a.y)',
    outputs: 1,
    js: M.sphereLightNormalization,
    range: [0, 1],
    args: cartesian(GRIDS.alpha, [0, 1e-4, 0.05, 0.5, 1]),
  },
  {
    name: 'equirectUv',
    chunk: 'env.glsl',
    glsl: 'equirectUv(a.xyz)',
    outputs: 2,
    js: (x, y, z) => M.equirectUv([x, y, z]),
    range: [0, 1],
    // away from the seam at u = 0 / 1 (atan2 of ±0), where both sides are right; the poles, where GLSL leaves
    // atan(0, 0) undefined (±0 alike: u = 1/2 by definition), a direction of length 2 and d = 0
    args: [
      ...[
        [0, 1, 0],
        [0, -1, 0],
        [1, 0, 0],
        [0, 0, 1],
        [0, 0, -1],
        [0.6, 0.8, 0],
        [-0.48, 0.6, 0.64],
        [0.3, -0.9, -0.3162],
        [0.01, 0.99, 0.01],
      ].map((d) => unitDir(...d)),
      [-0, 1, -0],
      [-0, -1, 0],
      [0, 2, 0],
      [0, 0, 0],
      [1.2, -1.6, 0],
    ],
  },
  {
    name: 'equirectDirection',
    chunk: 'env.glsl',
    glsl: 'equirectDirection(a.xy)',
    outputs: 3,
    js: M.equirectDirection,
    range: [-1, 1],
    args: cartesian([0, 0.1, 0.5, 0.77, 1], [0, 0.2, 0.5, 0.9, 1]),
    tolerance: TRIG_TOLERANCE,
  },
  {
    // the MERL table coordinates of (l, v): node units (θh sqrt-spaced 0-90, θd 0-90, φd 0-180). l at azimuth 0.3,
    // v at 0.6, 1, 2, 2.8 and π + 0.1 (nearly opposite, h near n), never in one plane with l and n:
    // there φd sits on its wrap at 0 / 180, where either side is right. A sphere's texture lookup filters over
    // 1/256 of a texel, so 2e-3 of a node is far below what shows.
    name: 'merlCoordinates',
    chunk: 'measured.glsl',
    glsl: 'merlCoordinates(vec3(0.0, 0.0, 1.0), a.xyz, b.xyz)',
    outputs: 3,
    js: (lx, ly, lz, _, vx, vy, vz) => {
      const a = M.halfDiffFromDirections([lx, ly, lz], [vx, vy, vz]);
      return merlCoordinates(a.thetaH, a.thetaD, a.phiD);
    },
    range: [0, 180],
    tolerance: { atol: 2e-3, rtol: 1e-4 },
    args: cartesian([0.02, 0.3, 0.7854, 1.2, 1.5], [0.02, 0.3, 0.7854, 1.2, 1.5], [0.6, 1, 2, 2.8, Math.PI + 0.1]).map(
      ([tl, tv, pv]) => [...spherical(tl, 0.3), 0, ...spherical(tv, pv), 0],
    ),
  },
  {
    // l = v: h = l, so d = l - h has no part across h and phi_d is atan(0, 0), which GLSL leaves undefined; at
    // theta_d = 0 every phi_d is the same pair of directions, and both sides take 0 (JS: the closed form θh = θl)
    name: 'merlCoordinates (l = v)',
    chunk: 'measured.glsl',
    glsl: 'merlCoordinates(vec3(0.0, 0.0, 1.0), a.xyz, a.xyz)',
    outputs: 3,
    js: (lx, ly, lz) => merlCoordinates(Math.atan2(Math.hypot(lx, ly), lz), 0, 0),
    range: [0, 180],
    tolerance: { atol: 2e-3, rtol: 1e-4 },
    args: cartesian([0, 1e-3, 0.3, 0.7854, 1.2, 1.5], [0, 0.3, 2, 4]).map(([t, p]) => spherical(t, p)),
  },
  {
    // the media tracer's random numbers (hi and lo 16 bits in): 32 bits over 2^32 round up to 1 for the top 128
    // values, and its free flight -log(1 - u) would take log(0), which GLSL leaves undefined. JS: the definition,
    // the top 24 bits over 2^24, in float64
    name: 'uniformFromBits (and -log(1 - u))',
    chunk: 'media.glsl',
    glsl: `vec2(${BITS_U}, -log(1.0 - ${BITS_U}))`,
    outputs: 2,
    js: (hi, lo) => {
      const u = Math.floor((hi * 65536 + lo) / 256) / 2 ** 24;
      return [u, -Math.log(1 - u)];
    },
    range: [0, 17],
    args: [
      [0, 0],
      [0, 255],
      [12345, 6789],
      [32768, 0],
      [65535, 65280],
      [65535, 65407],
      [65535, 65535],
    ],
  },
  {
    name: 'transmittance',
    chunk: 'media.glsl',
    glsl: 'transmittance(a.x, a.y)',
    outputs: 1,
    js: M.transmittance,
    range: [0, 1],
    args: cartesian([-1, 0, 1e-6, 0.3, 1, 50, 1e4], [-1, 0, 1e-3, 1, 100, 1e5]),
  },
  {
    name: 'fresnelZone',
    chunk: 'zones.glsl',
    glsl: 'fresnelZone(a.x)',
    outputs: 1,
    js: M.fresnelZone,
    range: [0, 2],
    args: cartesian(GRIDS.cos),
  },
  {
    name: 'ndfGGX',
    chunk: 'ndf.glsl',
    glsl: 'ndfGGX(a.x, a.y)',
    outputs: 1,
    js: M.ndfGGX,
    range: [0, Infinity],
    args: cartesian(GRIDS.cos, GRIDS.alpha),
  },
  {
    name: 'ndfBeckmann',
    chunk: 'ndf.glsl',
    glsl: 'ndfBeckmann(a.x, a.y)',
    outputs: 1,
    js: M.ndfBeckmann,
    range: [0, Infinity],
    args: cartesian(GRIDS.cos, GRIDS.alpha),
  },
  // cosines whose squares times alpha² underflow float32 (and may be flushed to 0): the forms that divide by them
  ...[
    ['ndfBeckmann', 'beckmann', [GRIDS.alpha]],
    ['ndfSGD', 'sgd', [GRIDS.sgdAlpha, GRIDS.sgdP]],
  ].map(([fn, key, params]) => {
    const term = CATALOGUE.ndf.terms[key];
    return {
      name: `${fn} (cos down to 1e-30)`,
      chunk: 'ndf.glsl',
      glsl: `${fn}(${slots(1 + params.length + (term.normaliser ? 1 : 0)).join(', ')})`,
      outputs: 1,
      js: M[fn],
      range: [0, Infinity],
      args: withNormaliser(term, cartesian(TINY_COS, ...params)),
    };
  }),
  {
    name: 'ndfBlinnPhong',
    chunk: 'ndf.glsl',
    glsl: 'ndfBlinnPhong(a.x, a.y)',
    outputs: 1,
    js: M.ndfBlinnPhong,
    range: [0, Infinity],
    args: cartesian(GRIDS.cos, GRIDS.exponent),
  },
  {
    name: 'smithG1GGX',
    chunk: 'visibility.glsl',
    glsl: 'smithG1GGX(a.x, a.y)',
    outputs: 1,
    js: M.smithG1GGX,
    range: [0, 1],
    args: cartesian(GRIDS.cos, GRIDS.alpha),
  },
  {
    name: 'smithG1Beckmann',
    chunk: 'visibility.glsl',
    glsl: 'smithG1Beckmann(a.x, a.y)',
    outputs: 1,
    js: M.smithG1Beckmann,
    range: [0, 1],
    args: cartesian(GRIDS.cos, GRIDS.alpha),
  },
  {
    name: 'smithG1BeckmannWalter',
    chunk: 'visibility.glsl',
    glsl: 'smithG1BeckmannWalter(a.x, a.y)',
    outputs: 1,
    js: M.smithG1BeckmannWalter,
    range: [0, 1],
    args: cartesian(GRIDS.cos, GRIDS.alpha),
  },
  {
    // grazing pairs on opposite sides (cos φ < 0): there 1 - 2b/π is multiplied by tan b ~ 1/cos b, and a GPU's
    // asin of a small cosine (llvmpipe's: 19 % off at 1e-7) was the whole error (diffuse.glsl)
    name: 'diffuseOrenNayar (grazing, cos φ < 0)',
    chunk: 'diffuse.glsl',
    glsl: 'diffuseOrenNayar(a.x, a.y, a.z, a.w, b.x)',
    outputs: 1,
    js: M.diffuseOrenNayar,
    range: [0, Infinity],
    tolerance: TERM_TOLERANCE.diffuseOrenNayar,
    args: cartesian(GRAZING, GRAZING, [-1, -0.7, -0.2], [0.2, 0.5, 1, Math.PI / 2], [0.3, 1]),
  },
  ...termParityCases(CATALOGUE),
  ...ANISOTROPIC_PARITY_CASES,
  ...F82_TINT_PARITY_CASES,
  ...OPENPBR_PARITY_CASES,
  ...dispatchParityCases(CATALOGUE, termAngles, FAMILY_RANGE),
];
